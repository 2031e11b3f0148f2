#include "harness/cli/numeric_flags.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <system_error>
#include <vector>

namespace shatter::cli {
namespace {

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (const char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

/// `digits` without leading zeros (one zero kept): decimal, never octal.
std::string decimal(std::string_view digits) {
  const std::size_t first = digits.find_first_not_of('0');
  return first == std::string_view::npos ? std::string("0") : std::string(digits.substr(first));
}

/// [+-]digits[.digits][(e|E)[+-]digits], or [+-].digits[...]: what strtod reads, without nan, inf and hex.
bool decimal_number(std::string_view s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (!all_digits(s.substr(i))) return false;
    return true;
  }
  return i == s.size();
}

std::string quote_text(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) out += static_cast<unsigned char>(c) < 0x20 ? '?' : c;
  return out + "\"";
}

/// The CLI11 type of `option` ("FLOAT", "INT", "UINT"), or "" for any other.
std::string numeric_type(const CLI::Option& option) {
  std::string name = option.get_type_name();
  name = name.substr(0, name.find(':'));
  for (const char* type : {"FLOAT", "INT", "UINT"})
    if (name == type) return type;
  return {};
}

}  // namespace

std::string numeric_flag_error(const std::string& type, std::string& text) {
  if (type == "FLOAT") {
    if (!decimal_number(text)) return "expected a decimal number, got " + quote_text(text);
    const double value = std::strtod(text.c_str(), nullptr);
    if (!std::isfinite(value)) return "must be a finite number, got " + quote_text(text);
    return {};
  }
  if (type == "INT" || type == "UINT") {
    const bool negative = type == "INT" && !text.empty() && text[0] == '-';
    const std::string_view digits = std::string_view(text).substr(negative ? 1 : 0);
    if (!all_digits(digits))
      return std::string(type == "INT" ? "expected an integer" : "expected a non-negative integer") + ", got " +
             quote_text(text);
    const std::string canonical = (negative ? "-" : "") + decimal(digits);
    std::errc ec{};
    if (type == "INT") {
      std::int64_t v = 0;
      ec = std::from_chars(canonical.data(), canonical.data() + canonical.size(), v).ec;
    } else {
      std::uint64_t v = 0;
      ec = std::from_chars(canonical.data(), canonical.data() + canonical.size(), v).ec;
    }
    if (ec != std::errc()) return "integer out of range, got " + quote_text(text);
    text = canonical;
    return {};
  }
  return {};
}

void check_numeric_flags(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    const std::string type = numeric_type(*option);
    if (type.empty()) continue;
    option->check(CLI::Validator([type](std::string& text) { return numeric_flag_error(type, text); }, ""));
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) check_numeric_flags(*sub);
}

}  // namespace shatter::cli
