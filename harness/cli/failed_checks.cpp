#include "harness/cli/failed_checks.h"

#include <cstdio>

namespace shatter::cli {

int print_failed_checks(std::string_view subject, const std::vector<std::string>& failed) {
  for (const std::string& check : failed) {
    std::string line = subject.empty() ? check : std::string(subject) + ": " + check;
    for (char& c : line)
      if (c == '\n' || c == '\r') c = ' ';
    std::fprintf(stderr, "shatterbench: check failed: %s\n", line.c_str());
  }
  return static_cast<int>(failed.size());
}

}  // namespace shatter::cli
