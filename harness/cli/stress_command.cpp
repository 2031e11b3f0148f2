#include "algorithms/registry/registries.h"
#include "algorithms/stress/propagation.h"
#include "harness/cases/case_library.h"
#include "harness/cases/case_mesh.h"
#include "harness/cases/run_settings.h"
#include "harness/cli/command.h"
#include "harness/pipeline/case_structure.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <string>

namespace shatter::cli {
namespace {

struct StressOptions {
  std::string case_name;
  std::string model;  // empty: the case's model
  bool json = false;
  bool no_repair = false;
  double cap_uv_scale = 0.0;  // 0: the case's
};

nlohmann::ordered_json vec_json(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

void print_json(const std::string& model, const SupportGraph& graph, const PropagationResult& p) {
  nlohmann::ordered_json bonds = nlohmann::ordered_json::array();
  for (int i = 0; i < graph.bond_count(); ++i) {
    const Bond& b = graph.bonds[static_cast<std::size_t>(i)];
    const BondStress& s = p.result.bonds[static_cast<std::size_t>(i)];
    bonds.push_back({{"a", b.a},
                     {"b", b.b},
                     {"area", b.area},
                     {"centroid", vec_json(b.centroid)},
                     {"normal", vec_json(b.normal)},
                     {"normal_force", std::abs(s.normal_force)},
                     {"tension", s.normal_force > 0},
                     {"shear_force", s.shear_force},
                     {"bending_moment", s.bending_moment},
                     {"torsion", s.torsion},
                     {"sigma", s.sigma},
                     {"sigma_tensile", s.tensile},
                     {"tau", s.tau},
                     {"utilization", s.utilization},
                     {"broken", s.broken}});
  }
  const nlohmann::ordered_json out = {
      {"model", model},
      {"fragments", graph.node_count()},
      {"bonds", bonds},
      {"falling_clusters", p.result.falling_clusters},
      {"break_order", p.break_order},
      {"rounds", p.rounds},
      {"solver",
       {{"solves", p.report.solves},
        {"iterations", p.report.iterations},
        {"converged", p.report.converged},
        {"residual", p.report.residual},
        {"unknowns", p.report.unknowns}}},
  };
  std::cout << out.dump(2) << '\n';
}

void print_table(const std::string& case_name, const std::string& model, const SupportGraph& graph,
                 const PropagationResult& p) {
  fmt::print("case {}: {} fragments, {} bonds, model {}\n\n", case_name, graph.node_count(), graph.bond_count(),
             model);
  fmt::print("| bond | a-b | centroid (m) | area m^2 | N (N) | V (N) | M (N m) | T (N m) | sigma (Pa) | tau (Pa) "
             "| utilization | broken |\n");
  fmt::print("|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
  for (int i = 0; i < graph.bond_count(); ++i) {
    const Bond& b = graph.bonds[static_cast<std::size_t>(i)];
    const BondStress& s = p.result.bonds[static_cast<std::size_t>(i)];
    fmt::print("| {} | {}-{} | ({:.3f}, {:.3f}, {:.3f}) | {:.4g} | {:.4g} | {:.4g} | {:.4g} | {:.4g} | {:.4g} | {:.4g} "
               "| {:.3f} | {} |\n",
               i, b.a, b.b, b.centroid.x(), b.centroid.y(), b.centroid.z(), b.area, s.normal_force, s.shear_force,
               s.bending_moment, s.torsion, s.sigma, s.tau, s.utilization, s.broken ? "yes" : "");
  }
  fmt::print("\nrounds of breaking: {}; falling clusters: {}; solves: {}, residual {:.2e}{}\n", p.rounds,
             p.result.falling_clusters.size(), p.report.solves, p.report.residual,
             p.report.converged ? "" : " (NOT converged)");
}

int run_stress(const StressOptions& o, const Registries& registries) {
  Result<Case> c = find_case(o.case_name);
  if (!c) return fail_input(c.error().message);
  if (o.no_repair) refuse_repair(*c);
  if (o.cap_uv_scale > 0.0) set_cap_uv_scale(*c, o.cap_uv_scale);
  CaseOverrides over;
  over.stress_model = o.model;
  const std::string model_name = resolve_settings(*c, over).stress_model;
  auto model = registries.stress_models.create(model_name, settings_for(model_name, c->stress.model, c->stress.settings));
  if (!model) return fail_algorithm(o.model.empty() ? c->name + ": stress.model" : "--model", model.error());
  Result<CaseStructure> structure = build_case_structure(*c, registries);
  if (!structure) return fail_algorithm("", structure.error());
  Loads loads;
  loads.gravity = c->gravity;
  const std::unique_ptr<StressSolver> solver = (*model)->make_solver(structure->graph, c->material);
  auto result = propagate(*solver, loads);
  if (!result) return fail_algorithm(c->name, result.error());
  // A solve that did not converge has no answer to print (its forces are not the structure's).
  if (!result->report.converged) return fail_check(c->name + ": " + convergence_failure(result->report));
  if (o.json)
    print_json(model_name, structure->graph, *result);
  else
    print_table(c->name, model_name, structure->graph, *result);
  return exit_ok;
}

}  // namespace

void add_stress_command(CLI::App& app, int& exit_code, const Registries& registries) {
  auto options = std::make_shared<StressOptions>();
  CLI::App* cmd = app.add_subcommand(
      "stress", "Pre-fracture a case, solve its structure, break what fails and report bonds and falling clusters");
  cmd->add_option("--case", options->case_name, "Case file or built-in case name (see `shatterbench list`)")
      ->required();
  cmd->add_option("--model", options->model, "Stress model (default: the case's stress.model)");
  cmd->add_flag("--json", options->json, "Print one JSON object instead of a table");
  cmd->add_flag("--no-repair", options->no_repair, "Refuse a mesh file that is not a solid instead of repairing it");
  add_cap_uv_scale_option(cmd, options->cap_uv_scale);
  cmd->callback([options, &exit_code, &registries] { exit_code = run_stress(*options, registries); });
}

}  // namespace shatter::cli
