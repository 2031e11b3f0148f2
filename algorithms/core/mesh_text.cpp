#include "algorithms/core/mesh_text.h"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace shatter {

namespace {

/// The characters std::isspace accepts in the "C" locale that can occur inside a line (line ends
/// are cut before), tested without a library call per character.
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

}  // namespace

bool TokenLines::next() {
  const char* const data = text_.data();
  const std::size_t size = text_.size();
  while (pos_ < size) {
    // One scan per line: it stops at the line's end, and notes the first '#' on the way.
    std::size_t end = pos_;
    std::size_t hash = std::string_view::npos;
    for (; end < size; ++end) {
      const char c = data[end];
      if (c == '\n' || c == '\r') break;
      if (c == '#' && hash == std::string_view::npos) hash = end;
    }
    const std::size_t line_end = hash != std::string_view::npos ? hash : end;
    const std::size_t line_start = pos_;
    pos_ = end + 1;
    if (end + 1 < size && data[end] == '\r' && data[end + 1] == '\n') ++pos_;  // "\r\n" is one end
    ++line_;
    tokens_.clear();
    std::size_t i = line_start;
    while (i < line_end) {
      while (i < line_end && is_blank(data[i])) ++i;
      const std::size_t start = i;
      while (i < line_end && !is_blank(data[i])) ++i;
      if (i > start) tokens_.emplace_back(data + start, i - start);
    }
    if (!tokens_.empty()) return true;
  }
  tokens_.clear();
  return false;
}

namespace {

/// The token quoted for a message, cut short when long (a message stays one short line).
std::string quoted(std::string_view token) {
  std::string out = "'";
  for (const char c : token.substr(0, 40)) out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  if (token.size() > 40) out += "...";
  return out + "'";
}

}  // namespace

Result<double> parse_finite_double(std::string_view token) {
  std::string_view s = token;
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty() || s.front() == '+') return Error{"non-numeric token " + quoted(token)};
  double value = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (end != s.data() + s.size() || ec == std::errc::invalid_argument) return Error{"non-numeric token " + quoted(token)};
  if (ec == std::errc::result_out_of_range) {
    // Overflow or underflow: strtod says which (HUGE_VAL for overflow, the rounding otherwise).
    value = std::strtod(std::string(s).c_str(), nullptr);
    if (!std::isfinite(value)) return Error{"number " + quoted(token) + " is outside the range of a double"};
    return value;
  }
  if (!std::isfinite(value)) return Error{"non-finite number " + quoted(token)};
  return value;
}

Result<std::int64_t> parse_integer(std::string_view token) {
  std::string_view s = token;
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec == std::errc::result_out_of_range) return Error{"integer " + quoted(token) + " is outside the range of 64 bits"};
  if (s.empty() || s.front() == '+' || ec != std::errc{} || end != s.data() + s.size())
    return Error{"non-numeric token " + quoted(token)};
  return value;
}

std::string joined_tokens(const std::vector<std::string_view>& tokens, std::size_t first) {
  std::string out;
  for (std::size_t i = first; i < tokens.size(); ++i) {
    if (i > first) out += ' ';
    out += tokens[i];
  }
  return out;
}

Status write_file_bytes(std::string_view bytes, const std::filesystem::path& path) {
  std::FILE* file = std::fopen(path.string().c_str(), "wb");
  if (file == nullptr) return Error{path.string() + ": cannot write: " + std::strerror(errno)};
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed) return Error{path.string() + ": write failed: " + std::strerror(errno)};
  return {};
}

}  // namespace shatter
