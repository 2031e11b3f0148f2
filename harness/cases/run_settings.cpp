#include "harness/cases/run_settings.h"

namespace shatter {
namespace {

std::string or_case(const std::string& option, const std::string& from_case) {
  return option.empty() ? from_case : option;
}

}  // namespace

RunSettings resolve_settings(const Case& c, const CaseOverrides& o) {
  RunSettings s;
  s.prefracture_fracturer = or_case(o.prefracture_fracturer, c.prefracture.fracturer);
  s.prefracturer = c.prefracture.explicit_planes() ? "planes" : s.prefracture_fracturer;
  s.runtime_fracturer = or_case(o.runtime_fracturer, c.runtime.fracturer);
  s.stress_model = or_case(o.stress_model, c.stress.model);
  s.prefracture_fragments = o.prefracture_fragments > 0 ? o.prefracture_fragments : c.prefracture.fragments;
  s.runtime_fragments = o.runtime_fragments > 0 ? o.runtime_fragments : c.runtime.fragments;
  s.frames = o.frames > 0 ? o.frames : c.frames;
  s.budget_ms = o.budget_ms > 0.0 ? o.budget_ms : c.budget_ms;
  s.schedule = o.schedule.value_or(c.schedule.mode);
  // An explicit-plane pre-fracture has one fragment count: the grid's pre-fracture axis collapses to it.
  if (c.prefracture.explicit_planes())
    s.prefracture_counts = {static_cast<int>(c.prefracture.planes.size()) + 1};
  else
    s.prefracture_counts = o.prefracture_counts.empty() ? c.grid.prefracture : o.prefracture_counts;
  s.runtime_counts = o.runtime_counts.empty() ? c.grid.runtime : o.runtime_counts;
  return s;
}

}  // namespace shatter
