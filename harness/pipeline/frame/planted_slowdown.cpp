#include "harness/pipeline/frame/planted_slowdown.h"

#include "harness/pipeline/physics/physics_world.h"
#include "harness/pipeline/stage.h"

#include <cstdint>
#include <cstdlib>

namespace shatter {
namespace {

#ifdef SHATTER_PLANTED_SLOWDOWN_SHARE
constexpr double kShare = SHATTER_PLANTED_SLOWDOWN_SHARE;
#else
constexpr double kShare = 0.0;
#endif

/// Arithmetic for `share` of `step_cpu_ms` of thread CPU time. Under callgrind, whose slowdown is about
/// the same per instruction for this loop and for Bullet, that is about the same share of the stage's
/// instructions.
void planted_work(double step_cpu_ms, double share) {
  const double until = thread_cpu_ms() + share * step_cpu_ms;
  volatile std::uint64_t x = 1;
  while (thread_cpu_ms() < until)
    for (int i = 0; i < 64; ++i) x = x * 6364136223846793005ULL + 1442695040888963407ULL;
}

}  // namespace

double planted_slowdown_share() {
  if constexpr (kShare > 0.0) {
    // The planted build only: SHATTER_PLANTED_SHARE sets another share, so one build measures the
    // smallest slowdown a gate finds (scripts/gate-power).
    static const double share = [] {
      const char* env = std::getenv("SHATTER_PLANTED_SHARE");
      const double v = env != nullptr ? std::strtod(env, nullptr) : kShare;
      return v >= 0.0 && v <= 10.0 ? v : kShare;
    }();
    return share;
  }
  return kShare;
}

void step_physics(PhysicsWorld& world) {
  if constexpr (kShare > 0.0) {
    const double step_start = thread_cpu_ms();
    world.step();
    planted_work(thread_cpu_ms() - step_start, planted_slowdown_share());
  } else {
    world.step();
  }
}

}  // namespace shatter
