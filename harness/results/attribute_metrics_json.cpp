#include "harness/results/attribute_metrics_json.h"

namespace shatter {

nlohmann::ordered_json attribute_metrics_json(const AttributeMetrics& a) {
  if (!a.measured) return nullptr;
  return {{"samples", a.samples},
          {"uv_error", a.uv_error},
          {"normal_error", a.normal_error},
          {"cap_normal_error", a.cap_normal_error},
          {"material_errors", a.material_errors}};
}

}  // namespace shatter
