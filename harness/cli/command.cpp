#include "harness/cli/command.h"

#include <cstdio>
#include <string>

namespace shatter::cli {

int fail_input(std::string_view message) {
  std::string line(message);
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  std::fprintf(stderr, "shatterbench: error: %s\n", line.c_str());
  return exit_bad_input;
}

}  // namespace shatter::cli
