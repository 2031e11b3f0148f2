#include "algorithms/stress/rigid_body_spring/inline_parallel_regions.h"

namespace shatter {

thread_local bool run_parallel_regions_inline = false;

}  // namespace shatter

// The interposition itself, only with the CMake option SHATTER_INLINE_PARALLEL_REGIONS (the flag above
// is defined either way, so that this unit is always linked and the guard always builds).
#ifdef SHATTER_INLINE_PARALLEL_REGIONS

#include <dlfcn.h>

/// libgomp's entry point of `#pragma omp parallel` (GCC 4.9 and later), defined here so that it takes
/// precedence over libgomp's for CHOLMOD's calls. Under SingleThreaded the region body runs as a plain
/// call on this thread: the same code a team of one runs (omp_get_num_threads() is 1 and
/// omp_get_thread_num() 0 outside a team, worksharing and barriers outside a team are valid and act on
/// this thread alone), without libgomp's team set-up and the futex wake-up at its closing barrier.
/// Everywhere else it forwards to libgomp's. What it saves is measured by evaluating the 23 x 22 wall
/// (`evaluate_wall` of benchmarks/stress_benchmarks.cpp) with the CMake option
/// SHATTER_INLINE_PARALLEL_REGIONS on and off.
extern "C" void GOMP_parallel(void (*fn)(void*), void* data, unsigned num_threads, unsigned flags) {
  if (shatter::run_parallel_regions_inline) {
    fn(data);
    return;
  }
  using Entry = void (*)(void (*)(void*), void*, unsigned, unsigned);
  static const Entry libgomp = reinterpret_cast<Entry>(dlsym(RTLD_NEXT, "GOMP_parallel"));
  libgomp(fn, data, num_threads, flags);
}

/// SuiteSparse's wall clock, which CHOLMOD 3.0.14 reads around every BLAS call of a supernodal
/// factorisation and solve for timing statistics (`cholmod_common` fields shatterbench never reads;
/// no setting turns them off). Under SingleThreaded it returns 0 without reading the clock: the
/// statistics are then 0, nothing else changes; on small systems the clock reads are a measurable share
/// of a solve (the same benchmark, the option on and off). Everywhere else it forwards to SuiteSparse's.
extern "C" double SuiteSparse_time(void) {
  if (shatter::run_parallel_regions_inline) return 0.0;
  using Entry = double (*)(void);
  static const Entry suitesparse = reinterpret_cast<Entry>(dlsym(RTLD_NEXT, "SuiteSparse_time"));
  return suitesparse();
}

#endif  // SHATTER_INLINE_PARALLEL_REGIONS
