#pragma once
/// The lexical layer of the mesh readers and writers: lines, tokens and strict numbers, and the one
/// file writer. Every reader splits its text here, so that "\n", "\r\n" and a lone "\r" (classic
/// Mac) all end a line and every limit that counts lines or statements holds whatever the line endings.

#include "algorithms/core/result.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace shatter {

/// Iterates over the non-empty lines of a text, with '#' comments stripped and tokens split.
class TokenLines {
 public:
  /// Iterates over `text`, which must outlive this object.
  explicit TokenLines(std::string_view text) : text_(text) {}
  /// Moves to the next line with at least one token; false at the end of the text.
  bool next();
  /// 1-based number of the current line (the last line at the end of the text).
  [[nodiscard]] std::int64_t line() const { return line_; }
  /// Tokens of the current line.
  [[nodiscard]] const std::vector<std::string_view>& tokens() const { return tokens_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::int64_t line_ = 0;
  std::vector<std::string_view> tokens_;
};

/// A token read whole as a finite double ("1", "-2.5e3", "+4"): anything else is an error saying why
/// (not a number, "1,5", "nan", "inf", or outside the range of a double such as "1e400"). A value
/// too small for a double (1e-400) reads as its rounding (0 or a subnormal).
Result<double> parse_finite_double(std::string_view token);

/// A token read whole as a decimal integer with an optional sign; an error saying why when it is not
/// one or does not fit 64 bits.
Result<std::int64_t> parse_integer(std::string_view token);

/// The tokens from `first` on, joined by single spaces (a name or path written with spaces).
std::string joined_tokens(const std::vector<std::string_view>& tokens, std::size_t first);

/// Writes `bytes` to `path` (created or truncated); an error names the file and the system's reason.
Status write_file_bytes(std::string_view bytes, const std::filesystem::path& path);

}  // namespace shatter
