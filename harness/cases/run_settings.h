#pragma once
/// The settings a run or a grid takes from a case and a command's options: the one place where "an
/// empty option means the case's value" is decided, for the grid, the pipeline and the commands.

#include "harness/cases/case.h"

#include <optional>
#include <string>
#include <vector>

namespace shatter {

/// What a command or a caller sets over a case. An empty name or list, a count or time of 0 and no
/// schedule each take the case's value.
struct CaseOverrides {
  std::string prefracture_fracturer;     ///< pre-fracture algorithm
  std::string runtime_fracturer;         ///< runtime algorithm
  std::string stress_model;              ///< stress model
  int prefracture_fragments = 0;         ///< pre-fracture count of one run
  int runtime_fragments = 0;             ///< pieces per hit fragment
  int frames = 0;                        ///< frames per run
  double budget_ms = 0.0;                ///< frame budget, ms
  std::optional<ScheduleMode> schedule;  ///< schedule mode of the runtime event
  std::vector<int> prefracture_counts;   ///< the grid's pre-fracture axis
  std::vector<int> runtime_counts;       ///< the grid's runtime axis
};

/// Every setting of a run or grid, resolved.
struct RunSettings {
  std::string prefracturer;              ///< pre-fracture algorithm as results name it ("planes" for explicit cuts)
  std::string prefracture_fracturer;     ///< pre-fracture algorithm to create (unused for explicit cuts)
  std::string runtime_fracturer;         ///< runtime algorithm
  std::string stress_model;              ///< stress model
  int prefracture_fragments = 0;         ///< pre-fracture count of one run
  int runtime_fragments = 0;             ///< pieces per hit fragment
  int frames = 0;                        ///< frames per run
  double budget_ms = 0.0;                ///< frame budget, ms
  ScheduleMode schedule = ScheduleMode::immediate;  ///< schedule mode of the runtime event
  std::vector<int> prefracture_counts;   ///< the grid's pre-fracture axis (explicit cuts: their one count)
  std::vector<int> runtime_counts;       ///< the grid's runtime axis
};

/// The settings of `c` with `overrides` applied (nothing is checked: names and counts are checked
/// where they are used, with errors naming the flag or the case key).
RunSettings resolve_settings(const Case& c, const CaseOverrides& overrides);

}  // namespace shatter
