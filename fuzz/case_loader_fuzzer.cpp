/// libFuzzer target: parse_case on arbitrary text must return a case or a one-line error naming the
/// source, never crash or throw.

#include "harness/cases/case_loader.h"

#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // The folder does not exist: relative mesh files resolve to nothing, built-in shapes still load.
  shatter::Result<shatter::Case> c = shatter::parse_case(text, "/nonexistent/fuzz_case.json");
  if (!c) {
    const std::string& message = c.error().message;
    if (message.empty() || message.find('\n') != std::string::npos) std::abort();
  }
  return 0;
}
