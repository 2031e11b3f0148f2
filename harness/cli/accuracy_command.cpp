#include "algorithms/fracture/fracture_limits.h"
#include "harness/limits.h"
#include "algorithms/fracture/fem_lite/fem_lite_settings.h"
#include "algorithms/registry/registries.h"
#include "harness/accuracy/accuracy_output.h"
#include "harness/accuracy/cascade_accuracy.h"
#include "harness/accuracy/collider_accuracy.h"
#include "harness/accuracy/fracture_accuracy.h"
#include "harness/accuracy/stress_accuracy.h"
#include "harness/cases/case_library.h"
#include "harness/cases/case_mesh.h"
#include "harness/cli/command.h"
#include "harness/cli/history_access.h"
#include "harness/cli/progress_line.h"
#include "harness/output/atomic_file.h"
#include "harness/output/output_targets.h"
#include "harness/results/run_context.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace shatter::cli {
namespace {

struct AccuracyOptions {
  std::vector<std::string> cases = {"elephant", "wall", "cantilever", "column", "fixed-beam"};
  std::string json;
  RecordFlags record;  // --record, --db
  int repetitions = 3;
  std::vector<std::string> families = {"fracture", "stress", "colliders", "cascade"};
  std::vector<std::string> fracturers;
  std::vector<std::string> models;
  std::vector<int> fragments = {5, 25, 100};
  std::vector<int> resolutions = {8, 16, 32};
  std::vector<int> slabs = {8, 16, 32, 64};
  std::vector<int> vertex_budgets = {0, 8, 16, 32, 64};
  bool no_repair = false;
  double cap_uv_scale = 0.0;  // 0: the case's
};

bool wants(const std::vector<std::string>& families, const char* family) {
  return std::find(families.begin(), families.end(), family) != families.end();
}

int run_accuracy(const AccuracyOptions& o, const Registries& registries) {
  // Everything is checked before anything runs, so bad input writes nothing.
  for (const std::string& f : o.families)
    if (f != "fracture" && f != "stress" && f != "colliders" && f != "cascade")
      return fail_input("--family: must be fracture, stress, colliders or cascade, got '" + f + "'");
  for (const std::string& name : o.fracturers) {
    auto f = registries.fracturers.create(name);
    if (!f) return fail_input("--fracturer: " + f.error().message);
    if ((*f)->exact_reference())
      return fail_input("--fracturer: " + name + " is the exact reference the others are measured against");
  }
  for (const std::string& name : o.models)
    if (auto m = registries.stress_models.create(name); !m) return fail_input("--model: " + m.error().message);
  // --resolution sets the sweep of every fracturer whose accuracy knob is `resolution`; each value is
  // checked by that fracturer's own settings.
  std::map<std::string, std::vector<double>, std::less<>> sweeps;
  sweeps["resolution"].assign(o.resolutions.begin(), o.resolutions.end());
  for (const std::string& name : o.fracturers.empty() ? default_accuracy_fracturers(registries) : o.fracturers) {
    for (const auto& [key, values] : accuracy_knobs(registries, name, sweeps)) {
      if (key != "resolution") continue;
      for (const double r : values)
        if (auto f = registries.fracturers.create(name, {{"resolution", r}}); !f)
          return fail_input("--resolution: " + f.error().message);
    }
  }
  for (const int b : o.vertex_budgets)
    if (b != 0 && (b < 4 || b > 256)) return fail_input(fmt::format("--vertex-budget: must be 0 or 4 to 256, got {}", b));
  for (const int n : o.slabs)
    if (n < 2 || n % 2 != 0 || n > 4096) return fail_input(fmt::format("--slabs: must be even, 2 to 4096, got {}", n));
  std::vector<Case> cases;
  for (const std::string& name : o.cases) {
    Result<Case> c = find_case(name);
    if (!c) return fail_input("--case: " + c.error().message);
    if (o.no_repair) refuse_repair(*c);
    if (o.cap_uv_scale > 0.0) set_cap_uv_scale(*c, o.cap_uv_scale);
    cases.push_back(std::move(*c));
  }
  const std::filesystem::path json_path = o.json;
  if (Status s = check_outputs({{"--json", json_path}}); !s) return fail_input(s.error().message);
  if (Status s = check_record_target(o.record); !s) return fail_input(s.error().message);

  const auto start = std::chrono::steady_clock::now();
  FractureAccuracyOptions fo;
  fo.fracturers = o.fracturers;
  fo.fragments = o.fragments;
  fo.sweeps = sweeps;
  fo.repetitions = o.repetitions;
  StressAccuracyOptions so;
  so.models = o.models;
  so.slabs = o.slabs;
  const int largest_slabs = *std::max_element(o.slabs.begin(), o.slabs.end());
  so.solver_slabs = largest_slabs >= 32 ? 32 : largest_slabs;
  so.repetitions = 10 * o.repetitions;  // a stress evaluation takes well under a millisecond: time it more often

  CascadeAccuracyOptions cao;
  cao.models = o.models;
  cao.repetitions = o.repetitions;

  ColliderAccuracyOptions co;
  co.budgets = o.vertex_budgets;
  co.fragments = o.fragments;
  co.repetitions = o.repetitions;

  std::vector<AccuracyPoint> points;
  std::vector<std::string> names;
  int steps = 0;
  for (const Case& c : cases)
    steps += (wants(o.families, "fracture") && !c.prefracture.explicit_planes() ? 1 : 0) +
             (wants(o.families, "colliders") && !c.prefracture.explicit_planes() ? 1 : 0) +
             (wants(o.families, "stress") ? 1 : 0) + (wants(o.families, "cascade") ? 1 : 0);
  ProgressLine progress("accuracy", steps);
  for (const Case& c : cases) {
    names.push_back(c.name);
    // Explicit planes make a fixed structure (the analytic beams): only its stress is measured.
    if (wants(o.families, "fracture") && !c.prefracture.explicit_planes()) {
      progress.step(c.name + ", fracture");
      Result<Solid> solid = build_case_solid(c);
      if (!solid) return progress.end(), fail_input(solid.error().message);
      std::optional<Impact> impact;
      if (!c.impacts.empty()) impact = c.impacts.front().impact;
      Result<std::vector<AccuracyPoint>> p = fracture_accuracy(c.name, *solid, impact, fo, registries);
      if (!p) return progress.end(), fail_input(p.error().message);
      points.insert(points.end(), p->begin(), p->end());
    }
    // The colliders of the case's own pre-fracture pieces at each budget.
    if (wants(o.families, "colliders") && !c.prefracture.explicit_planes()) {
      progress.step(c.name + ", colliders");
      Result<Solid> solid = build_case_solid(c);
      if (!solid) return progress.end(), fail_input(solid.error().message);
      Result<std::vector<AccuracyPoint>> p =
          collider_accuracy(c.name, *solid, c.prefracture.fracturer, co, registries);
      if (!p) return progress.end(), fail_input(p.error().message);
      points.insert(points.end(), p->begin(), p->end());
    }
    if (wants(o.families, "stress")) {
      progress.step(c.name + ", stress");
      Result<std::vector<AccuracyPoint>> p = stress_accuracy(c, so, registries);
      if (!p) return progress.end(), fail_input(p.error().message);
      points.insert(points.end(), p->begin(), p->end());
    }
    if (wants(o.families, "cascade")) {
      progress.step(c.name + ", cascade");
      Result<std::vector<AccuracyPoint>> p = cascade_accuracy(c, cao, registries);
      if (!p) return progress.end(), fail_input(p.error().message);
      points.insert(points.end(), p->begin(), p->end());
    }
  }
  progress.end();
  // Fracture rows first, then stress, then colliders, then cascades, each in run order.
  const auto rank = [](const std::string& family) {
    return family == "fracture" ? 0 : family == "stress" ? 1 : family == "colliders" ? 2 : 3;
  };
  std::stable_sort(points.begin(), points.end(),
                   [&](const AccuracyPoint& a, const AccuracyPoint& b) { return rank(a.family) < rank(b.family); });
  mark_pareto_front(points);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Every point is printed; one whose fracture fails its own checks makes the run fail, and so does a
  // stress point of the default solver whose solve did not converge (or failed). The solver sweeps (CG
  // with loose tolerances or capped iterations) are expected to stop short: their points are marked
  // failed in the table and the JSON only.
  std::vector<std::pair<std::string, std::vector<std::string>>> failed;
  for (const AccuracyPoint& p : points) {
    const std::string subject = p.case_name + " " + p.algorithm + " " + p.knob;
    if (p.figures.contains("failed_checks"))
      failed.emplace_back(subject, p.figures["failed_checks"].get<std::vector<std::string>>());
    if (p.family == "stress" && p.figures.contains("failed") && p.knobs.value("solver", "default") == "default")
      failed.emplace_back(subject, std::vector<std::string>{p.figures["failed"].get<std::string>()});
    if (p.family == "cascade" && p.figures.contains("failed"))
      failed.emplace_back(subject, std::vector<std::string>{p.figures["failed"].get<std::string>()});
  }
  std::cout << accuracy_to_markdown(points) << std::flush;
  if (!json_path.empty() || o.record.record) {
    nlohmann::ordered_json j = accuracy_to_json(points, names, o.repetitions, wall_s, current_context());
    j["passed"] = failed.empty();
    const std::string json = j.dump(1) + "\n";
    if (!json_path.empty())
      if (Status s = write_file_atomically(json_path, json); !s) return fail_input("--json: " + s.error().message);
    if (const int code = record_if_asked(o.record, json, json_path.empty() ? "accuracy.json" : json_path.string());
        code != exit_ok)
      return code;
  }
  int failed_checks = 0;
  for (const auto& [subject, messages] : failed) failed_checks += print_failed_checks(subject, messages);
  return failed_checks > 0 ? exit_gate_failed : exit_ok;
}

}  // namespace

void add_accuracy_command(CLI::App& app, int& exit_code, const Registries& registries) {
  auto o = std::make_shared<AccuracyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "accuracy", "Time every fracturer and stress model over its knobs against its error; mark the Pareto front");
  cmd->add_option("--case", o->cases, "Case files or built-in names (default: elephant wall cantilever column fixed-beam)");
  cmd->add_option("--json", o->json, "Write the accuracy results JSON here (docs/results.md)");
  add_record_flags(cmd, o->record);
  cmd->add_flag("--no-repair", o->no_repair, "Refuse a mesh file that is not a solid instead of repairing it");
  add_cap_uv_scale_option(cmd, o->cap_uv_scale);
  cmd->add_option("--repetitions", o->repetitions,
                  "Timed runs per fracture point (stress points: 10 x); the median is reported")
      ->check(CLI::Range(1, kMaxRepetitions))
      ->capture_default_str();
  cmd->add_option("--family", o->families, "Families to run: fracture, stress, colliders, cascade (default all four)");
  cmd->add_option("--vertex-budget", o->vertex_budgets,
                  "Collider vertex budgets of the colliders family (0 = every point, the exact path)")
      ->capture_default_str();
  cmd->add_option("--fracturer", o->fracturers, "Fracturers (default: every registered one but the exact reference, cgal-clip)");
  cmd->add_option("--model", o->models, "Stress models (default: every registered one)");
  cmd->add_option("--fragments", o->fragments, "Requested fragment counts")
      ->check(CLI::Range(1, kMaxFragments))
      ->capture_default_str();
  cmd->add_option("--resolution", o->resolutions, "Values of the resolution knob (fem-lite's grid cells along the longest axis)")->capture_default_str();
  cmd->add_option("--slabs", o->slabs, "Slab counts of the analytic beam and column cases (even)")->capture_default_str();
  cmd->callback([o, &exit_code, &registries] { exit_code = run_accuracy(*o, registries); });
}

}  // namespace shatter::cli
