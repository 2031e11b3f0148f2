#include "harness/cli/command.h"

#include <cstdio>
#include <string>

namespace shatter::cli {

namespace {

void print_line(const char* prefix, std::string_view message) {
  std::string line(message);
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  std::fprintf(stderr, "shatterbench: %s: %s\n", prefix, line.c_str());
}

}  // namespace

int fail_input(std::string_view message) {
  print_line("error", message);
  return exit_bad_input;
}

int fail_check(std::string_view message) {
  print_line("check failed", message);
  return exit_gate_failed;
}

int print_failed_checks(std::string_view subject, const std::vector<std::string>& failed) {
  for (const std::string& check : failed) print_line("check failed", subject.empty() ? check : std::string(subject) + ": " + check);
  return static_cast<int>(failed.size());
}

}  // namespace shatter::cli
