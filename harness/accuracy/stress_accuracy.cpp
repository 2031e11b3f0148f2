#include "harness/accuracy/stress_accuracy.h"

#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"
#include "harness/accuracy/beam_reference.h"
#include "harness/pipeline/case_structure.h"
#include "harness/plugins/capable_fracturer.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

namespace shatter {
namespace {

/// One structure the models run on, with what it is measured against.
struct Structure {
  SupportGraph graph;
  int slabs = 0;                          // 0: the case's own pre-fracture
  std::optional<BeamReference> beam;      // the closed form, when there is one
  StressResult reference;                 // the reference solve (von Mises, Eigen LDL^T)
  std::vector<int> first_failure;         // bonds that are the correct first failure
};

/// One model at one knob setting.
struct Setting {
  std::unique_ptr<StressModel> model;
  std::string knob;
  nlohmann::ordered_json knobs;
};

/// The bond of largest utilization (lowest index on ties) and how many bonds share that value.
std::pair<int, int> most_utilized(const StressResult& r) {
  int best = -1, ties = 0;
  for (int i = 0; i < static_cast<int>(r.bonds.size()); ++i) {
    const double u = r.bonds[static_cast<std::size_t>(i)].utilization;
    if (best < 0 || u > r.bonds[static_cast<std::size_t>(best)].utilization) {
      best = i;
      ties = 1;
    } else if (u == r.bonds[static_cast<std::size_t>(best)].utilization) {
      ++ties;
    }
  }
  return {best, ties};
}

Result<Structure> make_structure(SupportGraph graph, int slabs, const std::optional<BeamReference>& beam,
                                 const Loads& loads, const Material& material) {
  Structure s;
  s.graph = std::move(graph);
  s.slabs = slabs;
  s.beam = beam;
  SpringSolverSettings exact;
  exact.reference = true;
  Result<StressResult> ref = StrengthCriterionModel(Criterion::von_mises, exact).evaluate(s.graph, loads, material);
  if (!ref) return ref.error();
  if (!ref->report.converged) return Error{"the reference solve: " + convergence_failure(ref->report)};
  s.reference = std::move(*ref);
  if (beam) {
    s.first_failure = beam_first_failure(*beam, s.graph);
  } else if (const auto [bond, ties] = most_utilized(s.reference); bond >= 0) {
    s.first_failure = {bond};
  }
  return s;
}

AccuracyPoint measure(const std::string& case_name, const Structure& s, const Setting& setting, const Loads& loads,
                      const Material& material, int repetitions) {
  AccuracyPoint p;
  p.family = "stress";
  p.case_name = case_name;
  p.algorithm = std::string(setting.model->name());
  p.knob = setting.knob;
  p.knobs = setting.knobs;
  StressResult result;
  // One solver for the repetitions, as a game keeps one per structure: from the second on, the
  // structure's solve reuses what the first kept (strength_criterion_solver.h).
  const std::unique_ptr<StressSolver> solver = setting.model->make_solver(s.graph, material);
  for (int rep = 0; rep < repetitions; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    Result<StressResult> r = solver->evaluate(loads);
    const auto t1 = std::chrono::steady_clock::now();
    if (!r) {
      p.time_ms = std::numeric_limits<double>::quiet_NaN();
      p.figures = {{"failed", r.error().message}};
      return p;
    }
    p.samples_ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    if (rep == 0) result = std::move(*r);
  }
  p.time_ms = median_of(p.samples_ms);

  const bool has_forces = setting.model->driven_by_loads();
  const auto [first, ties] = most_utilized(result);
  // A match needs every bond tied at the largest utilization to be one the reference fails first: a
  // rule that rates every bond alike has not found the first failure.
  bool match = first >= 0;
  for (int i = 0; i < static_cast<int>(result.bonds.size()) && match; ++i)
    if (result.bonds[static_cast<std::size_t>(i)].utilization == result.bonds[static_cast<std::size_t>(first)].utilization)
      match = std::find(s.first_failure.begin(), s.first_failure.end(), i) != s.first_failure.end();
  p.figures = {{"bonds", s.graph.bond_count()},
               {"reference", s.beam ? std::string(beam_kind_name(s.beam->kind)) : std::string("reference solve")}};
  if (has_forces) {
    const double vs_solve = sigma_error(result, s.reference);
    p.figures["analytic_error"] = s.beam ? nlohmann::ordered_json(beam_error(*s.beam, s.graph, result)) : nullptr;
    p.figures["solver_error"] = vs_solve;
    p.figures["residual"] = result.report.residual;
    p.figures["converged"] = result.report.converged;
    p.figures["iterations"] = result.report.iterations;
    p.error = s.beam ? p.figures["analytic_error"].get<double>() : vs_solve;
    if (!std::isfinite(*p.error)) p.error.reset();
  } else {
    p.figures["analytic_error"] = nullptr;
    p.figures["solver_error"] = nullptr;
  }
  p.figures["max_utilization"] = first >= 0 ? result.bonds[static_cast<std::size_t>(first)].utilization : 0.0;
  p.figures["first_bond"] = first;
  p.figures["first_bond_ties"] = ties;
  p.figures["first_bond_expected"] = s.first_failure;
  p.figures["first_bond_match"] = match;
  if (has_forces && !result.report.converged) {
    // Its forces are not an answer: the point is marked failed and has no error (off the Pareto
    // front); its residual and iterations stay, as a capped CG sweep is measured for exactly that.
    p.figures["failed"] = convergence_failure(result.report);
    p.error.reset();
  }
  return p;
}

/// Whether `model` documents the keys of the CG solver sweep (cg_only, cg_tolerance, max_iterations).
bool has_cg_sweep(const StressModelRegistry& models, const std::string& model) {
  int found = 0;
  for (const SettingDoc& d : models.settings(model))
    found += d.key == "cg_only" || d.key == "cg_tolerance" || d.key == "max_iterations" ? 1 : 0;
  return found == 3;
}

/// The settings of `name` swept on a structure: the default one, plus the CG solver knobs when `solver`
/// and the model documents them (has_cg_sweep).
Result<std::vector<Setting>> model_settings(const StressModelRegistry& models, const std::string& name,
                                            const std::string& prefix, bool solver, const nlohmann::ordered_json& base,
                                            const StressAccuracyOptions& o) {
  std::vector<Setting> out;
  Result<std::unique_ptr<StressModel>> model = models.create(name);
  if (!model) return model.error();
  nlohmann::ordered_json knobs = base;
  knobs["solver"] = "default";
  out.push_back({std::move(*model), prefix + "solver=default", knobs});
  if (!solver || !has_cg_sweep(models, name)) return out;
  const auto add_cg = [&](double tolerance, int cap) -> Status {
    const PluginSettings settings = {{"cg_only", true}, {"cg_tolerance", tolerance}, {"max_iterations", double(cap)}};
    Result<std::unique_ptr<StressModel>> cg = models.create(name, settings);
    if (!cg) return cg.error();
    nlohmann::ordered_json k = base;
    k["solver"] = "cg";
    k["cg_tolerance"] = tolerance;
    k["cg_max_iterations"] = cap;
    out.push_back({std::move(*cg), prefix + fmt::format("solver=cg tol={:.0e} cap={}", tolerance, cap), k});
    return {};
  };
  const SpringSolverSettings defaults;
  for (const double tolerance : o.cg_tolerances)
    if (Status s = add_cg(tolerance, defaults.cg_max_iterations); !s) return s.error();
  for (const int cap : o.cg_iteration_caps)
    if (Status s = add_cg(1e-12, cap); !s) return s.error();
  return out;
}

}  // namespace

double sigma_error(const StressResult& r, const StressResult& reference) {
  double scale = 0.0, worst = 0.0;
  for (const BondStress& b : reference.bonds) scale = std::max(scale, b.sigma);
  for (std::size_t i = 0; i < r.bonds.size(); ++i)
    worst = std::max(worst, std::abs(r.bonds[i].sigma - reference.bonds[i].sigma));
  return scale > 0.0 ? worst / scale : worst;
}

Result<std::vector<AccuracyPoint>> stress_accuracy(const Case& c, const StressAccuracyOptions& o,
                                                   const Registries& registries) {
  const std::vector<std::string> models = o.models.empty() ? registries.stress_models.names() : o.models;
  Loads loads;
  loads.gravity = c.gravity;
  std::vector<Structure> structures;
  const std::optional<BeamReference> beam = classify_beam_case(c);
  if (beam) {
    std::vector<int> counts = o.slabs;
    if (std::find(counts.begin(), counts.end(), o.solver_slabs) == counts.end()) counts.push_back(o.solver_slabs);
    Result<std::unique_ptr<Fracturer>> cutter =
        plane_cutter(registries.fracturers, c.prefracture.fracturer, c.prefracture.settings);
    if (!cutter) return Error{c.source.string() + ": prefracture.planes: " + cutter.error().message};
    for (const int n : counts) {
      Result<SupportGraph> g = beam_structure(*beam, n, *(*cutter)->plane_cutting());
      if (!g) return Error{c.source.string() + ": " + g.error().message};
      Result<Structure> s = make_structure(std::move(*g), n, beam, loads, c.material);
      if (!s) return Error{c.source.string() + ": " + s.error().message};
      structures.push_back(std::move(*s));
    }
  } else {
    Result<CaseStructure> cs = build_case_structure(c, registries);
    if (!cs) return cs.error();
    Result<Structure> s = make_structure(std::move(cs->graph), 0, std::nullopt, loads, c.material);
    if (!s) return Error{c.source.string() + ": " + s.error().message};
    structures.push_back(std::move(*s));
  }

  std::vector<AccuracyPoint> points;
  for (const std::string& name : models) {
    for (const Structure& s : structures) {
      const bool in_slab_sweep = std::find(o.slabs.begin(), o.slabs.end(), s.slabs) != o.slabs.end();
      const bool solver_sweep = s.slabs == 0 || s.slabs == o.solver_slabs;
      nlohmann::ordered_json base = nlohmann::ordered_json::object();
      std::string prefix;
      if (s.slabs > 0) {
        base["slabs"] = s.slabs;
        prefix = fmt::format("slabs={} ", s.slabs);
      }
      Result<std::vector<Setting>> settings = model_settings(registries.stress_models, name, prefix, solver_sweep, base, o);
      if (!settings) return settings.error();
      for (std::size_t k = 0; k < settings->size(); ++k) {
        if (k == 0 && !in_slab_sweep && s.slabs > 0) continue;  // default solver only on swept slab counts
        points.push_back(measure(c.name, s, (*settings)[k], loads, c.material, o.repetitions));
      }
    }
  }
  return points;
}

}  // namespace shatter
