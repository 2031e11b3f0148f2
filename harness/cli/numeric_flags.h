#pragma once
/// Strict reading of every numeric flag of the CLI, in one place.
///
/// Design note: CLI11 converts a flag's text with strtod / strtoll / strtoull, which take "nan",
/// "inf", "1e3" for a count, hex ("0x10"), octal ("010"), and wrap or saturate out of range ("-1" as
/// an unsigned seed is 2^64 - 1, "99999999999999999999" saturates). Rather than a check per flag,
/// every option whose value is a number gets one validator from its CLI11 type (FLOAT, INT, UINT):
///  - FLOAT: a decimal number ([+-]digits[.digits][e[+-]digits]) that is finite in double;
///  - INT: [-]digits within a signed 64-bit integer; UINT: digits within an unsigned 64-bit integer;
///    leading zeros are read as decimal, never octal. CLI11 then refuses a value that does not fit
///    the flag's narrower type.
/// Each flag's own range (> 0, [1, limit]) stays with the flag. A refused value is exit 2 with one
/// line naming the flag (tests/hostile/wrong_answers_numbers_tests.cpp, "numbers: flags ...").

#include <CLI/CLI.hpp>

#include <string>

namespace shatter::cli {

/// Adds the strict numeric validator to every numeric option of `app` and of its subcommands, at any
/// depth. Call once, after every command is added and before parsing.
void check_numeric_flags(CLI::App& app);

/// The error of the validator for a CLI11 type name ("FLOAT", "INT", "UINT") and a value: empty when
/// `text` is a valid number of that type; `text` may be rewritten to its canonical decimal form.
std::string numeric_flag_error(const std::string& type, std::string& text);

}  // namespace shatter::cli
