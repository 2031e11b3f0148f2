#pragma once
/// What `shatterbench accuracy` prints and writes: a Markdown table per family and the accuracy
/// results JSON (docs/results.md, "Accuracy results JSON").

#include "harness/accuracy/accuracy_point.h"
#include "harness/results/run_context.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace shatter {

/// Schema version of the accuracy results JSON.
inline constexpr int kAccuracySchemaVersion = 1;

/// The Markdown tables: "## fracture" then "## stress", one row per point in the given order; the
/// Pareto column holds "**front**" for points on the front. A family with no point is left out.
std::string accuracy_to_markdown(const std::vector<AccuracyPoint>& points);

/// The results JSON: `schema_version`, `kind` ("accuracy"), `context`, `repetitions`, `cases`,
/// `wall_s`, `points`.
nlohmann::ordered_json accuracy_to_json(const std::vector<AccuracyPoint>& points, const std::vector<std::string>& cases,
                                        int repetitions, double wall_s, const RunContext& context);

}  // namespace shatter
