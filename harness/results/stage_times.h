#pragma once
/// The names of the stages of a destruction run (DESIGN.md section 3) and the per-stage figures results
/// hold: the vocabulary shared by the pipeline that times the stages and every results writer and
/// reader. The timers and the record of which stages ran live with the pipeline (pipeline/stage.h).

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

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

/// The stage named `name` (stage_name's inverse), or nullopt for a name no stage has.
std::optional<Stage> stage_from_name(std::string_view name);

/// Milliseconds (or, in instruction mode, retired instructions) per stage, indexed by Stage.
using StageTimes = std::array<double, kStageCount>;

/// One skip: the stage (or the part of it) that did not run, and why.
struct StageSkip {
  std::string stage;   ///< stage name
  std::string reason;  ///< one line, e.g. "no anchors: every component falls, nothing to solve"
};

}  // namespace shatter
