#pragma once
/// Which existing files a command may replace: only its own kind of output (docs/cli.md, "Outputs").
///
/// Design note: a file named as an output may be one the user keeps (a thesis, a CSV of their own
/// beside a JSON), so an existing file is replaced only when its first bytes are those of a file
/// shatterbench writes: a JSON document with shatterbench's context block (its build fingerprint and
/// library versions), the grid CSV's header, a JUnit report of shatterbench's suites, or the compare
/// comment's heading. An empty file holds nothing to lose. Anything else is refused before the command
/// runs, with one line.

#include <filesystem>

namespace shatter {

/// True when the regular file `file` is empty or starts as a file shatterbench writes (above); false
/// when it cannot be read.
bool is_own_output_file(const std::filesystem::path& file);

}  // namespace shatter
