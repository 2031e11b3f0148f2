#pragma once
/// Text from files (case names, algorithm names, messages) made safe for a Markdown page: it stays
/// data, whatever it holds.

#include <string>

namespace shatter {

/// `text` for one cell of a Markdown table: control characters (a newline would end the row) become
/// spaces, `|` (a column break) and `\` are escaped with `\`, and `<`, `>`, `&` become HTML entities, so
/// that no input opens a tag or an element in a renderer that allows HTML.
std::string markdown_cell(const std::string& text);

}  // namespace shatter
