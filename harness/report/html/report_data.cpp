#include "harness/report/html/report_data.h"

#include <nlohmann/json.hpp>

namespace shatter {
namespace {

using Json = nlohmann::ordered_json;

/// `{"file": ..., "results": ...}` for every item of `files` (each with `file` and `document`).
template <typename Files>
Json entries(const Files& files) {
  Json out = Json::array();
  for (const auto& f : files) out.push_back(Json{{"file", f.file}, {"results", f.document}});
  return out;
}

}  // namespace

std::string report_data_json(const ReportInputs& inputs) {
  const Json data = {
      {"format", 1},
      {"grids", entries(inputs.grids)},
      {"accuracy", entries(inputs.accuracies)},
      {"stability", entries(inputs.stabilities)},
      {"tables", entries(inputs.tables)},
  };
  // Strict UTF-8: every string was checked when the file was parsed.
  return data.dump();
}

}  // namespace shatter
