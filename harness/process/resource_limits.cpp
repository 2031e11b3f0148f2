#include "harness/process/resource_limits.h"

#include <sys/resource.h>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SHATTER_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define SHATTER_SANITIZED 1
#endif
#endif

namespace shatter {

bool sanitized_build() {
#if defined(SHATTER_SANITIZED)
  return true;
#else
  return false;
#endif
}

bool limit_this_process(std::uint64_t memory_bytes, double cpu_s) {
  const auto set = [](int resource, rlim_t value) {
    const rlimit r{value, value};
    return ::setrlimit(resource, &r) == 0;
  };
  bool ok = set(RLIMIT_FSIZE, 0) && set(RLIMIT_CORE, 0);
  ok = ok && set(RLIMIT_CPU, static_cast<rlim_t>(cpu_s) + 1);
  if (!sanitized_build()) ok = ok && set(RLIMIT_AS, static_cast<rlim_t>(memory_bytes));
  return ok;
}

}  // namespace shatter
