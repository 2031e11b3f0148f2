#include "harness/stability/stability_table.h"

#include <fmt/format.h>

namespace shatter {
namespace {

/// Keeps a cell on one line and free of the column separator.
std::string cell(std::string text) {
  for (char& c : text)
    if (c == '|' || c == '\n' || c == '\r') c = ' ';
  return text;
}

}  // namespace

std::string stability_table(const std::vector<HazardResult>& results) {
  std::string out =
      "| hazard | algorithm | outcome | worst error | fragments | converged | residual | time ms | detail |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  for (const HazardResult& r : results) {
    const bool stress = r.kind == "stress";
    out += fmt::format("| {} | {} | {} | {:.3g} | {} | {} | {} | {:.0f} | {} |\n", cell(r.hazard), cell(r.algorithm),
                       outcome_tag(r.outcome), r.worst_error, r.fragments,
                       stress ? (r.converged ? "yes" : "no") : "-",
                       stress ? fmt::format("{:.3g}", r.residual) : std::string("-"), r.time_ms, cell(r.detail));
  }
  return out;
}

nlohmann::ordered_json stability_json(const std::vector<HazardResult>& results, bool quick, double time_limit_s) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const HazardResult& r : results) rows.push_back(to_json(r));
  return {{"quick", quick}, {"time_limit_s", time_limit_s}, {"results", rows}};
}

}  // namespace shatter
