#pragma once
/// Limits a child process puts on itself before it runs code that may run away (an importer, the
/// mesh repair): its address space, CPU time, files written and core dumps (setrlimit).

#include <cstdint>

namespace shatter {

/// Under AddressSanitizer, ThreadSanitizer or MemorySanitizer, which reserve terabytes of address
/// space for their shadow memory: the address space is then not limited, and time budgets are
/// scaled by kSanitizerSlowdown.
bool sanitized_build();

/// How much slower the same work runs in a sanitized build (the factor time budgets are scaled by).
inline constexpr double kSanitizerSlowdown = 10.0;

/// Limits the calling process (meant for a forked child): address space `memory_bytes` (unless
/// sanitized_build()), CPU time `cpu_s` seconds (then SIGXCPU), no file larger than 0 bytes written
/// (SIGXFSZ) and no core dump. False when the kernel refuses one.
bool limit_this_process(std::uint64_t memory_bytes, double cpu_s);

}  // namespace shatter
