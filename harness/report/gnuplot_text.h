#pragma once
/// Text from results files in gnuplot charts, as data only (docs/report.md, "No text reaches a shell").
///
/// Design note: gnuplot runs backquoted text inside a double-quoted string of a script as a shell
/// command, expands `@` macros, and starts a new command at a newline, so no text that came from a
/// file (a case name, an algorithm or stage name) is ever written into a script. The script is fixed
/// text the tool composes from its own words and numbers; every outside string goes into a data file,
/// one quoted field each, and the script reads it into a variable with `strcol` (a string read from
/// data is a value, never parsed as commands) or labels points with a data column.

#include <string>
#include <vector>

namespace shatter {

/// `text` as one double-quoted field of a gnuplot data file: a `"` becomes `'`, a `\` is doubled (gnuplot
/// reads `\\` as one), and control characters become spaces, so the field cannot end early, escape its
/// quote or end the line.
std::string gnuplot_data_field(const std::string& text);

/// Strings a script shows (titles, legend entries), kept in a data file of their own.
class GnuplotStrings {
 public:
  /// Adds `text` and returns the script variable that holds it once load() has run ("text_3").
  std::string add(const std::string& text);
  /// The data file: one line of quoted fields, one per string added.
  [[nodiscard]] std::string data() const;
  /// The script line that reads `file` (a name the tool made, relative to the script's folder) into
  /// the variables; empty when no string was added.
  [[nodiscard]] std::string load(const std::string& file) const;

 private:
  std::vector<std::string> texts_;
};

}  // namespace shatter
