#include "harness/report/gnuplot_text.h"

namespace shatter {

std::string gnuplot_data_field(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) out += ' ';
    else if (c == '"') out += '\'';
    else if (c == '\\') out += "\\\\";
    else out += c;
  }
  return out + "\"";
}

std::string GnuplotStrings::add(const std::string& text) {
  texts_.push_back(text);
  return "text_" + std::to_string(texts_.size() - 1);
}

std::string GnuplotStrings::data() const {
  std::string line;
  for (const std::string& t : texts_) line += (line.empty() ? "" : " ") + gnuplot_data_field(t);
  return line + "\n";
}

std::string GnuplotStrings::load(const std::string& file) const {
  if (texts_.empty()) return {};
  std::string assignments;
  for (std::size_t i = 0; i < texts_.size(); ++i)
    assignments += "text_" + std::to_string(i) + " = strcol(" + std::to_string(i + 1) + "), ";
  return "stats \"" + file + "\" using (" + assignments + "0) nooutput\n";
}

}  // namespace shatter
