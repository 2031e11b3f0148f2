#pragma once
/// The named stages of a destruction run (DESIGN.md section 3), their timers and the record of which
/// ran and which were skipped, and why.
///
/// Design note: a stage is a unit with a name and a clock, not a class hierarchy: the run is a
/// sequence of setup functions, event phases and frame steps (docs/pipeline.md section 7), and each
/// stage is a function call wrapped in a StageTimer.
/// Times are kept per stage twice: `setup` (offline work before frame 0: pre-fracture, bonds, the
/// first stress solve, the first colliders) and `frames` (work inside frames, summed over the run:
/// the runtime event's stages and the physics steps). Only the second counts against the frame budget.

#include "harness/pipeline/instruction_marks.h"

#include <array>
#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace shatter {

/// The stages in data-flow order.
enum class Stage : int {
  prefracture,       ///< offline fracture of the solid (cached on disk)
  bonds,             ///< support graph and anchors
  runtime_fracture,  ///< the impact fractures the fragment(s) it reaches
  bond_update,       ///< bonds of the fractured fragments are removed
  stress,            ///< stress solve, break, re-solve until stable
  falling_clusters,  ///< components with no path to an anchor fall
  colliders,         ///< Bullet convex hulls with exact mass properties
  physics,           ///< Bullet steps of 1/60 s
  debris,            ///< debris and dust particles: spawned per event, integrated each frame
};

/// Number of stages.
inline constexpr std::size_t kStageCount = 9;

/// Every stage in data-flow order.
inline constexpr std::array<Stage, kStageCount> kAllStages = {
    Stage::prefracture, Stage::bonds,     Stage::runtime_fracture, Stage::bond_update,
    Stage::stress,      Stage::falling_clusters, Stage::colliders,  Stage::physics, Stage::debris};

/// The stage's name in results and tables, e.g. "runtime_fracture".
std::string_view stage_name(Stage stage);

/// Milliseconds per stage.
using StageTimes = std::array<double, kStageCount>;

/// One skip: the stage (or the part of it) that did not run, and why.
struct StageSkip {
  std::string stage;   ///< stage name
  std::string reason;  ///< one line, e.g. "no anchors: every component falls, nothing to solve"
};

/// Which stages ran and which were skipped in one run. A stage can be in both lists when part of its
/// work was skipped (the fragments outside an impact's radius are not fractured).
class StageLog {
 public:
  /// Records that `stage` ran (once per stage).
  void ran(Stage stage);
  /// Records a skip of `stage` with `reason` (an identical skip is recorded once).
  void skipped(Stage stage, std::string reason);
  /// Stage names that ran, in data-flow order.
  [[nodiscard]] std::vector<std::string> run() const;
  /// Skips in the order they happened.
  [[nodiscard]] const std::vector<StageSkip>& skips() const { return skips_; }

 private:
  std::array<bool, kStageCount> ran_{};
  std::vector<StageSkip> skips_;
};

/// The CPU time this thread has used, ms (CLOCK_THREAD_CPUTIME_ID: time the thread was descheduled
/// does not count, which makes it the steadier figure on a shared machine).
double thread_cpu_ms();

/// Wall and thread CPU time per stage, ms.
struct StageClocks {
  StageTimes wall{};  ///< what a player sees: the frame budget is on wall time
  StageTimes cpu{};   ///< the thread's CPU time: what `compare` tests by default
};

/// Adds the wall and CPU time of its scope to one stage of a StageClocks, in ms; in instruction mode
/// it also marks the scope for callgrind (instruction_marks.h).
class StageTimer {
 public:
  StageTimer(StageClocks& clocks, Stage stage)
      : stage_(stage),
        wall_(clocks.wall[static_cast<std::size_t>(stage)]),
        cpu_(clocks.cpu[static_cast<std::size_t>(stage)]) {
    instruction_marks::begin();
    cpu_start_ = thread_cpu_ms();
    start_ = std::chrono::steady_clock::now();
  }
  ~StageTimer() {
    wall_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    cpu_ += thread_cpu_ms() - cpu_start_;
    instruction_marks::end(stage_name(stage_));
  }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  Stage stage_;
  double& wall_;
  double& cpu_;
  double cpu_start_ = 0.0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace shatter
