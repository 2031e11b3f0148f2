#include "harness/accuracy/accuracy_output.h"

#include "harness/results/markdown_text.h"

#include <fmt/core.h>

#include <cmath>

namespace shatter {
namespace {

using Json = nlohmann::ordered_json;

/// A figure as table text: "-" when absent or null, yes/NO for booleans, 2 significant digits otherwise.
std::string cell(const Json& figures, const char* key) {
  if (!figures.contains(key) || figures[key].is_null()) return "-";
  const Json& v = figures[key];
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "NO";
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  if (v.is_number()) return fmt::format("{:.2e}", v.get<double>());
  return v.get<std::string>();
}

std::string time_text(double ms) { return std::isfinite(ms) ? fmt::format("{:.3f}", ms) : "failed"; }

std::string error_text(const AccuracyPoint& p) { return p.error ? fmt::format("{:.2e}", *p.error) : "-"; }

std::string front_text(const AccuracyPoint& p) { return p.pareto ? "**front**" : ""; }

bool has_family(const std::vector<AccuracyPoint>& points, const std::string& family) {
  for (const AccuracyPoint& p : points)
    if (p.family == family) return true;
  return false;
}

}  // namespace

std::string accuracy_to_markdown(const std::vector<AccuracyPoint>& points) {
  std::string out;
  if (has_family(points, "fracture")) {
    out += "## fracture\n\n";
    out += "| case | fracturer | knob | fragments | time ms | replay error | volume error | partition error "
           "| area error | closed | Pareto |\n";
    out += "|---|---|---|---:|---:|---:|---:|---:|---:|---|---|\n";
    for (const AccuracyPoint& p : points) {
      if (p.family != "fracture") continue;
      if (p.figures.contains("failed") && !p.figures.contains("fragments")) {
        out += fmt::format("| {} | {} | {} | - | failed | - | - | - | - | - | {} |\n", markdown_cell(p.case_name), markdown_cell(p.algorithm), markdown_cell(p.knob),
                           markdown_cell(p.figures["failed"].get<std::string>()));
        continue;
      }
      out += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", markdown_cell(p.case_name), markdown_cell(p.algorithm),
                         markdown_cell(p.knob), cell(p.figures, "fragments"), time_text(p.time_ms), error_text(p),
                         cell(p.figures, "volume_error"), cell(p.figures, "partition_error"),
                         cell(p.figures, "area_error"), cell(p.figures, "all_closed"), front_text(p));
    }
    out += "\nreplay error = max(largest per-fragment |V - V_exact| / V_exact against the exact CGAL replay of the "
           "same cuts, unpaired volume share); time = median of the repetitions; front = Pareto front of time "
           "and replay error per case\n\n";
  }
  if (has_family(points, "stress")) {
    out += "## stress\n\n";
    out += "| case | model | knob | bonds | time ms | error | analytic error | solver error | first bond | "
           "first bond ok | Pareto |\n";
    out += "|---|---|---|---:|---:|---:|---:|---:|---:|---|---|\n";
    for (const AccuracyPoint& p : points) {
      if (p.family != "stress") continue;
      if (p.figures.contains("failed")) {
        out += fmt::format("| {} | {} | {} | - | failed | - | - | - | - | - | {} |\n", markdown_cell(p.case_name), markdown_cell(p.algorithm), markdown_cell(p.knob),
                           markdown_cell(p.figures["failed"].get<std::string>()));
        continue;
      }
      std::string first = cell(p.figures, "first_bond");
      if (const auto ties = p.figures.find("first_bond_ties");
          ties != p.figures.end() && ties->is_number() && ties->get<double>() > 1)
        first += fmt::format(" (tie of {:g})", ties->get<double>());
      out += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", markdown_cell(p.case_name), markdown_cell(p.algorithm),
                         markdown_cell(p.knob), cell(p.figures, "bonds"), time_text(p.time_ms), error_text(p),
                         cell(p.figures, "analytic_error"), cell(p.figures, "solver_error"), first,
                         cell(p.figures, "first_bond_match"), front_text(p));
    }
    out += "\nerror = analytic error (largest relative error of bond moments / peak stresses against beam theory) "
           "where the case has a closed form, else solver error (largest |sigma - sigma_ref| / max sigma_ref against "
           "the reference LDL^T solve of the same structure); connection-count computes no forces: no error, only "
           "its most utilized bond against the reference's first failure; front = Pareto front per case\n";
  }
  if (has_family(points, "colliders")) {
    out += "\n## colliders\n\n";
    out += "| case | pieces of | knob | pieces | time ms | largest volume cut off | mean volume cut off "
           "| points per collider | Pareto |\n";
    out += "|---|---|---|---:|---:|---:|---:|---:|---|\n";
    for (const AccuracyPoint& p : points) {
      if (p.family != "colliders") continue;
      const auto named = p.knobs.find("fracturer");
      const std::string fracturer =
          markdown_cell(named != p.knobs.end() && named->is_string() ? named->get<std::string>() : std::string("-"));
      if (p.figures.contains("failed")) {
        out += fmt::format("| {} | {} | {} | - | failed | - | - | - | {} |\n", markdown_cell(p.case_name), fracturer, markdown_cell(p.knob),
                           markdown_cell(p.figures["failed"].get<std::string>()));
        continue;
      }
      out += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", markdown_cell(p.case_name), fracturer, markdown_cell(p.knob),
                         cell(p.figures, "pieces"), time_text(p.time_ms), error_text(p),
                         cell(p.figures, "mean_volume_loss"), cell(p.figures, "mean_points"), front_text(p));
    }
    out += "\ntime = building every piece's collider (median of the repetitions); volume cut off = 1 - V(hull of "
           "the collider's points) / V(hull of all the piece's points), per piece; every_point is the exact path, "
           "the budgets drop the points that cannot be hull corners first, as the pipeline does; front = "
           "Pareto front per case\n";
  }
  if (has_family(points, "cascade")) {
    out += "\n## cascade\n\n";
    out += "| case | model | knob | bonds | time ms | error | broken / exact | falling / exact | rounds / exact "
           "| round error | Pareto |\n";
    out += "|---|---|---|---:|---:|---:|---|---|---|---:|---|\n";
    for (const AccuracyPoint& p : points) {
      if (p.family != "cascade") continue;
      if (p.figures.contains("failed")) {
        out += fmt::format("| {} | {} | {} | {} | failed | - | - | - | - | - | {} |\n", markdown_cell(p.case_name), markdown_cell(p.algorithm),
                           markdown_cell(p.knob), cell(p.figures, "bonds"), markdown_cell(p.figures["failed"].get<std::string>()));
        continue;
      }
      out += fmt::format("| {} | {} | {} | {} | {} | {} | {} / {} | {} / {} | {} / {} | {} | {} |\n", markdown_cell(p.case_name),
                         markdown_cell(p.algorithm), markdown_cell(p.knob), cell(p.figures, "bonds"), time_text(p.time_ms), error_text(p),
                         cell(p.figures, "broken"), cell(p.figures, "reference_broken"), cell(p.figures, "falling"),
                         cell(p.figures, "reference_falling"), cell(p.figures, "rounds"),
                         cell(p.figures, "reference_rounds"), cell(p.figures, "round_error"), front_text(p));
    }
    out += "\ntime = a whole cascade (median of the repetitions, one solver kept for all); the structure loses the "
           "bonds of the fragment nearest the first impact, its strengths scaled so that the exact solve puts "
           "its most utilized bond at 1.5; error = the larger of the shares of bonds broken and of fragments "
           "falling in one cascade and not in the exact one; round error = one round from the exact cascade's "
           "first state, largest |sigma - sigma_ref| / max sigma_ref; front = Pareto front per case\n";
  }
  return out;
}

nlohmann::ordered_json accuracy_to_json(const std::vector<AccuracyPoint>& points, const std::vector<std::string>& cases,
                                        int repetitions, double wall_s, const RunContext& context) {
  Json j;
  j["schema_version"] = kAccuracySchemaVersion;
  j["kind"] = "accuracy";
  j["context"] = to_json(context);
  j["repetitions"] = repetitions;
  j["cases"] = cases;
  j["wall_s"] = wall_s;
  Json list = Json::array();
  for (const AccuracyPoint& p : points) {
    Json e;
    e["family"] = p.family;
    e["case"] = p.case_name;
    e["algorithm"] = p.algorithm;
    e["knob"] = p.knob;
    e["knobs"] = p.knobs;
    e["time_ms"] = std::isfinite(p.time_ms) ? Json(p.time_ms) : Json(nullptr);
    e["samples_ms"] = p.samples_ms;
    e["error"] = p.error ? Json(*p.error) : Json(nullptr);
    e["pareto"] = p.pareto;
    e["figures"] = p.figures;
    list.push_back(std::move(e));
  }
  j["points"] = std::move(list);
  return j;
}

}  // namespace shatter
