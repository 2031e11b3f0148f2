#pragma once
/// The stability report: a Markdown table for people and a JSON document for tools.

#include "harness/stability/hazard_outcome.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace shatter {

/// One row per result: hazard, algorithm, outcome, worst error, fragments, solver figures, time, detail.
std::string stability_table(const std::vector<HazardResult>& results);

/// {"quick", "time_limit_s", "results": [...]} with one object per result (to_json).
nlohmann::ordered_json stability_json(const std::vector<HazardResult>& results, bool quick, double time_limit_s);

}  // namespace shatter
