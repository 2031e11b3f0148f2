#include "harness/cli/command.h"

#include "harness/limits.h"

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

void add_cap_uv_scale_option(CLI::App* cmd, double& out) {
  cmd->add_option("--cap-uv-scale", out,
                  "Metres per UV unit on cut faces of a solid with attributes (default: the case's, else the "
                  "largest side of the solid's box)")
      ->check(CLI::Validator(
          [](const std::string& text) {
            double value = 0.0;
            return CLI::detail::lexical_cast(text, value) && value >= kLengthRange.min && value <= kLengthRange.max
                       ? std::string()
                       : "must be a length in [1e-06, 1e+06] m, got " + text;
          },
          "METRES"));
}

int fail_check(std::string_view message) {
  print_line("check failed", message);
  return exit_gate_failed;
}

int fail_algorithm(std::string_view context, const Error& error) {
  const std::string line = context.empty() ? error.message : std::string(context) + ": " + error.message;
  return error.cause == ErrorCause::algorithm_fault ? fail_check(line) : fail_input(line);
}

int print_failed_checks(std::string_view subject, const std::vector<std::string>& failed) {
  for (const std::string& check : failed) print_line("check failed", subject.empty() ? check : std::string(subject) + ": " + check);
  return static_cast<int>(failed.size());
}

}  // namespace shatter::cli
