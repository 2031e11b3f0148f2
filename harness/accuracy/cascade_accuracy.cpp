#include "harness/accuracy/cascade_accuracy.h"

#include "harness/accuracy/stress_accuracy.h"
#include "harness/pipeline/case_structure.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

namespace shatter {
namespace {

/// One model at one setting.
struct Setting {
  std::unique_ptr<StressModel> model;
  std::string knob;
  nlohmann::ordered_json knobs;
};

/// The holed structure's exact cascade and its first round, which every model is measured against.
struct Reference {
  PropagationResult cascade;
  StressResult first_state;        // the first round's input: the holed solve with its failures flagged
  std::vector<int> first_touched;  // the ends of the first round's failures
  StressResult first_round;        // the exact solve of that round
};

/// The holed structure's start: `hole` flagged broken, no displacements (a cascade's start).
StressResult holed(const SupportGraph& graph, const std::vector<int>& hole) {
  StressResult start;
  start.bonds.resize(graph.bonds.size());
  for (const int b : hole) start.bonds[static_cast<std::size_t>(b)].broken = true;
  return start;
}

std::vector<int> every_node(const SupportGraph& graph) {
  std::vector<int> all(graph.nodes.size());
  std::iota(all.begin(), all.end(), 0);
  return all;
}

Result<Reference> reference_cascade(const SupportGraph& graph, const Loads& loads, const Material& material,
                                    const StressModel& exact, const std::vector<int>& hole) {
  const std::unique_ptr<StressSolver> solver = exact.make_solver(graph, material);
  Reference r;
  Result<PropagationResult> cascade = propagate(*solver, loads, hole);
  if (!cascade) return cascade.error();
  if (!cascade->report.converged) return Error{"the reference cascade: " + convergence_failure(cascade->report)};
  r.cascade = std::move(*cascade);
  Result<StressResult> start = solver->reevaluate(loads, holed(graph, hole), every_node(graph));
  if (!start) return start.error();
  r.first_state = std::move(*start);
  for (std::size_t i = 0; i < graph.bonds.size(); ++i) {
    BondStress& b = r.first_state.bonds[i];
    if (b.broken || b.utilization <= 1.0) continue;
    b.broken = true;
    r.first_touched.push_back(graph.bonds[i].a);
    r.first_touched.push_back(graph.bonds[i].b);
  }
  if (!r.first_touched.empty()) {
    Result<StressResult> round = solver->reevaluate(loads, r.first_state, r.first_touched);
    if (!round) return round.error();
    r.first_round = std::move(*round);
  }
  return r;
}

/// The default setting of `name`, then one per value of each documented accuracy sweep.
Result<std::vector<Setting>> model_settings(const StressModelRegistry& models, const std::string& name) {
  std::vector<Setting> out;
  Result<std::unique_ptr<StressModel>> model = models.create(name);
  if (!model) return model.error();
  out.push_back({std::move(*model), "default", nlohmann::ordered_json::object()});
  for (const SettingDoc& d : models.settings(name)) {
    for (const double v : d.accuracy_sweep) {
      Result<std::unique_ptr<StressModel>> m = models.create(name, {{d.key, v}});
      if (!m) return m.error();
      nlohmann::ordered_json knobs;
      knobs[d.key] = v;
      out.push_back({std::move(*m), fmt::format("{}={}", d.key, v), knobs});
    }
  }
  return out;
}

AccuracyPoint measure(const std::string& case_name, const SupportGraph& graph, const Setting& setting,
                      const Loads& loads, const Material& material, const std::vector<int>& hole,
                      const Reference& reference, double overload, int repetitions) {
  AccuracyPoint p;
  p.family = "cascade";
  p.case_name = case_name;
  p.algorithm = std::string(setting.model->name());
  p.knob = setting.knob;
  p.knobs = setting.knobs;
  p.figures = {{"bonds", graph.bond_count()}, {"hole", static_cast<int>(hole.size())}, {"overload", overload}};
  // One solver for the repetitions, as a game keeps one per structure across events.
  const std::unique_ptr<StressSolver> solver = setting.model->make_solver(graph, material);
  PropagationResult result;
  for (int rep = 0; rep < repetitions; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    Result<PropagationResult> r = propagate(*solver, loads, hole);
    const auto t1 = std::chrono::steady_clock::now();
    if (!r || !r->report.converged) {
      p.time_ms = std::numeric_limits<double>::quiet_NaN();
      p.figures["failed"] = !r ? r.error().message : convergence_failure(r->report);
      return p;
    }
    p.samples_ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    if (rep == 0) result = std::move(*r);
  }
  p.time_ms = median_of(p.samples_ms);

  const CascadeComparison d = compare_cascades(result, reference.cascade, graph.node_count());
  p.figures["rounds"] = result.rounds;
  p.figures["reference_rounds"] = reference.cascade.rounds;
  p.figures["broken"] = d.broken;
  p.figures["reference_broken"] = d.reference_broken;
  p.figures["broken_mismatch"] = d.broken_share();
  p.figures["falling"] = d.falling;
  p.figures["reference_falling"] = d.reference_falling;
  p.figures["falling_mismatch"] = d.falling_share();
  p.figures["round_error"] = nullptr;
  if (!reference.first_touched.empty()) {
    Result<StressResult> round = solver->reevaluate(loads, reference.first_state, reference.first_touched);
    if (round && round->report.converged) p.figures["round_error"] = sigma_error(*round, reference.first_round);
  }
  p.error = std::max(d.broken_share(), d.falling_share());
  return p;
}

}  // namespace

double CascadeComparison::broken_share() const {
  return static_cast<double>(broken_mismatch) / std::max(1, reference_broken);
}

double CascadeComparison::falling_share() const {
  return static_cast<double>(falling_mismatch) / std::max(1, reference_falling);
}

CascadeComparison compare_cascades(const PropagationResult& cascade, const PropagationResult& reference, int nodes) {
  CascadeComparison d;
  for (std::size_t i = 0; i < cascade.result.bonds.size(); ++i) {
    const bool a = cascade.result.bonds[i].broken, b = reference.result.bonds[i].broken;
    d.broken += a ? 1 : 0;
    d.reference_broken += b ? 1 : 0;
    d.broken_mismatch += a != b ? 1 : 0;
  }
  const auto falling = [nodes](const PropagationResult& r) {
    std::vector<std::uint8_t> f(static_cast<std::size_t>(nodes), 0);
    for (const std::vector<int>& cluster : r.result.falling_clusters)
      for (const int v : cluster) f[static_cast<std::size_t>(v)] = 1;
    return f;
  };
  const std::vector<std::uint8_t> fa = falling(cascade), fb = falling(reference);
  for (std::size_t v = 0; v < fa.size(); ++v) {
    d.falling += fa[v];
    d.reference_falling += fb[v];
    d.falling_mismatch += fa[v] != fb[v] ? 1 : 0;
  }
  return d;
}

Result<std::vector<AccuracyPoint>> cascade_accuracy(const Case& c, const CascadeAccuracyOptions& o,
                                                    const Registries& registries) {
  const std::vector<std::string> models = o.models.empty() ? registries.stress_models.names() : o.models;
  Result<CaseStructure> cs = build_case_structure(c, registries);
  if (!cs) return cs.error();
  const SupportGraph& graph = cs->graph;
  Loads loads;
  loads.gravity = c.gravity;

  // The hole: the bonds of the fragment nearest the first impact (none without an impact).
  std::vector<int> hole;
  if (!c.impacts.empty() && graph.node_count() > 0) {
    const Vec3 at = c.impacts.front().impact.point;
    int nearest = 0;
    for (int v = 1; v < graph.node_count(); ++v)
      if ((graph.nodes[static_cast<std::size_t>(v)].centroid - at).squaredNorm() <
          (graph.nodes[static_cast<std::size_t>(nearest)].centroid - at).squaredNorm())
        nearest = v;
    hole = graph.node_bonds[static_cast<std::size_t>(nearest)];
  }

  // The models grouped by their exact reference (StressModel::exact_cascade_reference, one group per
  // reference name), in the order the models come; a model that states none is left out.
  struct Group {
    std::unique_ptr<StressModel> reference;
    std::vector<std::string> models;
  };
  std::vector<Group> groups;
  std::vector<AccuracyPoint> points;
  for (const std::string& name : models) {
    Result<std::unique_ptr<StressModel>> model = registries.stress_models.create(name);
    if (!model) return model.error();
    std::unique_ptr<StressModel> reference = (*model)->exact_cascade_reference();
    if (reference == nullptr) continue;
    const auto same = [&](const Group& g) { return g.reference->name() == reference->name(); };
    if (const auto it = std::find_if(groups.begin(), groups.end(), same); it != groups.end())
      it->models.push_back(name);
    else
      groups.push_back({std::move(reference), {name}});
  }
  for (const Group& group : groups) {
    // Strengths scaled so that the exact solve of the holed structure peaks at `overload`.
    Result<StressResult> start =
        group.reference->make_solver(graph, c.material)->reevaluate(loads, holed(graph, hole), every_node(graph));
    if (!start) return Error{c.source.string() + ": " + start.error().message};
    double peak = 0.0;
    for (const BondStress& b : start->bonds)
      if (!b.broken) peak = std::max(peak, b.utilization);
    if (!(peak > 0.0) || !std::isfinite(peak))
      return Error{c.source.string() + ": no bond of the structure carries a load, so nothing can cascade"};
    Material material = c.material;
    const double k = peak / o.overload;
    material.tensile_strength *= k;
    material.compressive_strength *= k;
    material.shear_strength *= k;
    Result<Reference> reference = reference_cascade(graph, loads, material, *group.reference, hole);
    if (!reference) return Error{c.source.string() + ": " + reference.error().message};
    for (const std::string& name : group.models) {
      Result<std::vector<Setting>> settings = model_settings(registries.stress_models, name);
      if (!settings) return settings.error();
      for (const Setting& s : *settings)
        points.push_back(measure(c.name, graph, s, loads, material, hole, *reference, o.overload, o.repetitions));
    }
  }
  return points;
}

}  // namespace shatter
