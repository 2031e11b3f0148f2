#pragma once
/// OpenMP regions run as plain calls while CHOLMOD runs under its single-thread guard
/// (SingleThreaded in supernodal_cholesky.cpp).
///
/// Design note: Debian's CHOLMOD opens an OpenMP region per supernode, and even a team of one costs
/// libgomp a team set-up and a futex wake-up per region. With the CMake option
/// SHATTER_INLINE_PARALLEL_REGIONS (ON by default), inline_parallel_regions.cpp defines libgomp's
/// `GOMP_parallel` (and SuiteSparse's `SuiteSparse_time`, which CHOLMOD reads around every BLAS call)
/// so that they take precedence over the libraries' own: while this thread's flag is set, a region
/// runs as a plain call and the clock is not read; everywhere else the calls go on to libgomp and
/// SuiteSparse. With the option OFF the flag is set all the same and nothing reads it: CHOLMOD then
/// runs its regions through libgomp, single-threaded, with the same results (docs/design.md, "Build").

namespace shatter {

/// Set while this thread is inside CHOLMOD under SingleThreaded: its OpenMP regions then run inline.
extern thread_local bool run_parallel_regions_inline;

}  // namespace shatter
