#pragma once
/// The physics step of a frame, with the test-only planted slowdown (CMake option
/// SHATTER_PLANTED_SLOWDOWN, docs/compare.md): in such a build every step is followed by arithmetic for
/// a share of the step's thread CPU time, to prove that `compare` catches a slowdown. Only this unit is
/// compiled differently; in every other build the step is the plain step.

namespace shatter {

class PhysicsWorld;

/// The share of a physics step's thread CPU time added as arithmetic after it: in a build with
/// SHATTER_PLANTED_SLOWDOWN 0.10, or the environment's SHATTER_PLANTED_SHARE (0 to 10); else 0.
double planted_slowdown_share();

/// One physics step of `world`, then the planted slowdown when the build has one.
void step_physics(PhysicsWorld& world);

}  // namespace shatter
