#pragma once
/// How a command says that its own checks found its result invalid (exit 1, one line per check).

#include <string>
#include <string_view>
#include <vector>

namespace shatter::cli {

/// Prints "shatterbench: check failed: <subject>: <check>" on stderr for every entry of `failed`
/// (newlines in them become spaces; "<subject>: " is left out when `subject` is empty) and returns
/// the number of lines printed.
int print_failed_checks(std::string_view subject, const std::vector<std::string>& failed);

}  // namespace shatter::cli
