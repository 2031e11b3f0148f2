#include "algorithms/stress/rigid_body_spring/local_cascade_model.h"

#include "algorithms/stress/rigid_body_spring/local_cascade_solver.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"

#include <memory>
#include <string>

namespace shatter {

std::unique_ptr<StressSolver> LocalCascadeModel::make_solver(const SupportGraph& graph,
                                                             const Material& material) const {
  return std::make_unique<LocalCascadeSolver>(graph, material, criterion_, settings_, hops_, exact_start_);
}

std::unique_ptr<StressModel> LocalCascadeModel::exact_cascade_reference() const {
  return StrengthCriterionModel(criterion_).exact_cascade_reference();
}

namespace {

std::vector<SettingDoc> local_setting_docs() {
  std::vector<SettingDoc> docs = {
      {"hops", "bonds", std::to_string(LocalCascadeModel::kDefaultHops), "[1, 1000000]",
       "a cascade round re-solves the nodes within this many intact bonds of its breaks", {1, 2, 4, 8}},
      {"exact_start", "", "0", "0 or 1",
       "1: a cascade's start (the breaks it is given) is solved exactly; 0: on the window around them, from the "
       "structure at rest",
       {0, 1}}};
  for (SettingDoc& d : spring_solver_setting_docs())
    if (d.key == "tolerance") {
      d.description = "relative residual |K u - f| / |f| a converged solve may leave";
      docs.push_back(std::move(d));
    }
  return docs;
}

void register_local(StressModelRegistry& registry, const char* name, const char* description, Criterion criterion) {
  registry.add(name, description, local_setting_docs(),
               [name, criterion](const PluginSettings& settings) -> Result<std::unique_ptr<StressModel>> {
                 const std::vector<SettingDoc> docs = local_setting_docs();
                 const SettingsReader r(name, settings, docs);
                 if (Status st = r.check_keys(); !st) return st.error();
                 int hops = LocalCascadeModel::kDefaultHops;
                 if (Status st = r.integer("hops", 1, 1000000, hops); !st) return st.error();
                 int exact_start = 0;
                 if (Status st = r.integer("exact_start", 0, 1, exact_start); !st) return st.error();
                 SpringSolverSettings s;
                 if (Status st = r.number_above("tolerance", 0.0, 1.0, s.residual_tolerance); !st) return st.error();
                 return std::unique_ptr<StressModel>(std::make_unique<LocalCascadeModel>(criterion, s, hops, exact_start != 0));
               });
}

}  // namespace

void register_local_cascade_models(StressModelRegistry& registry) {
  register_local(registry, "tresca-local",
                 "tresca, with each cascade round re-solved only around its breaks (within `hops` bonds)",
                 Criterion::tresca);
  register_local(registry, "von-mises-local",
                 "von-mises, with each cascade round re-solved only around its breaks (within `hops` bonds)",
                 Criterion::von_mises);
}

}  // namespace shatter
