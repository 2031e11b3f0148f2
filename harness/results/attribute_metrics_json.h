#pragma once
/// The `attributes` object of `fracture`'s metrics and of `accuracy`'s figures (docs/cli.md).

#include "harness/metrics/attribute_metrics.h"

#include <nlohmann/json.hpp>

namespace shatter {

/// `{"samples", "uv_error", "normal_error", "cap_normal_error", "material_errors"}` of `a`, or null
/// when the input carried no attributes (nothing was measured).
nlohmann::ordered_json attribute_metrics_json(const AttributeMetrics& a);

}  // namespace shatter
