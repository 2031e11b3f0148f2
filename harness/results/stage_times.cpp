#include "harness/results/stage_times.h"

namespace shatter {

std::string_view stage_name(Stage stage) {
  switch (stage) {
    case Stage::prefracture: return "prefracture";
    case Stage::bonds: return "bonds";
    case Stage::runtime_fracture: return "runtime_fracture";
    case Stage::bond_update: return "bond_update";
    case Stage::stress: return "stress";
    case Stage::falling_clusters: return "falling_clusters";
    case Stage::colliders: return "colliders";
    case Stage::physics: return "physics";
    case Stage::debris: return "debris";
  }
  return "unknown";
}

std::optional<Stage> stage_from_name(std::string_view name) {
  for (const Stage s : kAllStages)
    if (stage_name(s) == name) return s;
  return std::nullopt;
}

}  // namespace shatter
