#pragma once
/// CHOLMOD single-threaded, for every solver that calls it (the stress solver's supernodal factor,
/// fem-lite's elastic solve): SingleThreadedCholmod bounds OpenMP while it is alive, and asks for the
/// OpenMP regions of this thread to run as plain calls.
///
/// Design note: Debian's CHOLMOD opens OpenMP teams of 4 threads for large supernodes; on 2 shared
/// cores the wake-ups cost more than they gain (docs/stress.md, section 3, item 4). Even a team of one
/// costs libgomp a team set-up and a futex wake-up per region, and CHOLMOD opens a region per
/// supernode. With the CMake option SHATTER_INLINE_PARALLEL_REGIONS (ON by default),
/// single_threaded_cholmod.cpp defines libgomp's `GOMP_parallel` (and SuiteSparse's `SuiteSparse_time`,
/// which CHOLMOD reads around every BLAS call) so that they take precedence over the libraries' own:
/// while this thread's flag is set, a region runs as a plain call and the clock is not read;
/// everywhere else the calls go on to libgomp and SuiteSparse. With the option OFF the flag is set all
/// the same and nothing reads it: CHOLMOD then runs its regions through libgomp, single-threaded, with
/// the same results (docs/design.md, "Build").

namespace shatter {

/// Set while this thread is inside CHOLMOD under SingleThreadedCholmod: its OpenMP regions then run inline.
extern thread_local bool run_parallel_regions_inline;

/// Runs CHOLMOD single-threaded while alive: the process-wide OpenMP nesting bound is 0 (restored on
/// exit; nothing else in shatterbench uses OpenMP) and this thread's regions run inline.
class SingleThreadedCholmod {
 public:
  SingleThreadedCholmod();
  ~SingleThreadedCholmod();
  SingleThreadedCholmod(const SingleThreadedCholmod&) = delete;
  SingleThreadedCholmod& operator=(const SingleThreadedCholmod&) = delete;

 private:
  int saved_levels_;
  bool saved_inline_;
};

}  // namespace shatter
