#pragma once
/// A fixed reference workload timed beside every repetition, so that `compare` can tell a slower
/// machine from slower code.
///
/// Design note: on a shared virtual machine other jobs and the hypervisor slow every stage at once;
/// the thread's CPU time does not escape that (time stolen by the hypervisor is billed to the thread).
/// The calibration workload does not change with the code under test, so its time measures the
/// machine's speed at that moment: `compare` divides each stage's CPU time by the calibration time of
/// the same repetition (the ratio is a speed-independent cost) before testing. A change that slows
/// one stage moves its ratio; a busier machine moves both and the ratio stays.

namespace shatter {

/// Thread CPU time, ms, of the reference workload (sorting and summing 2^16 pseudo-random doubles,
/// twice; 5 to 10 ms on this machine, depending on its load). Deterministic work.
double calibration_ms();

}  // namespace shatter
