#include "harness/plugins/plugin_guard.h"

#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/fracture/fracture_output_check.h"
#include "algorithms/stress/stress_output_check.h"

#include <exception>
#include <memory>
#include <optional>
#include <utility>
#include <variant>

namespace shatter {
namespace {

/// Runs `call`; any exception out of it is an Error "<who> threw: <what>" (one printable line).
template <class Call>
Status contained(const std::string& who, Call&& call) {
  try {
    call();
    return {};
  } catch (const std::exception& e) {
    const char* what = e.what();
    return Error{who + " threw: " + one_printable_line(what != nullptr ? what : ""), ErrorCause::algorithm_fault};
  } catch (...) {
    return Error{who + " threw an exception that is not a std::exception", ErrorCause::algorithm_fault};
  }
}

/// A plugin's own error, made one printable line (its cause as the plugin gave it).
Error outside_error(const Error& e) { return Error{one_printable_line(e.message), e.cause}; }

/// A check's error as the fault of the algorithm that returned the result.
Error fault(const Status& s) { return Error{s.error().message, ErrorCause::algorithm_fault}; }

/// Error unless every plane of `plan` is usable (check_planes) and a schedule asks for a fragment
/// count within the limit.
Status check_cut_plan(const CutPlan& plan) {
  if (const auto* schedule = std::get_if<RecursiveCutSchedule>(&plan)) {
    if (schedule->fragments < 1 || schedule->fragments > kMaxFragments)
      return Error{"a schedule of " + std::to_string(schedule->fragments) + " fragments (1 to " +
                   std::to_string(kMaxFragments) + ")"};
    return {};
  }
  if (const auto* cuts = std::get_if<PlaneCuts>(&plan)) return check_planes(cuts->planes);
  const auto& cells = std::get<CellCuts>(plan).cells;
  if (cells.empty() || cells.size() > static_cast<std::size_t>(kMaxFragments))
    return Error{std::to_string(cells.size()) + " cells (1 to " + std::to_string(kMaxFragments) + ")"};
  for (const ConvexCell& cell : cells)
    if (Status s = check_planes(cell.planes); !s) return s;
  return {};
}

class GuardedFracturer final : public Fracturer, public PlaneCutting, public CutPlanReplay {
 public:
  GuardedFracturer(std::string name, std::unique_ptr<Fracturer> inner)
      : name_(std::move(name)), who_("fracturer '" + name_ + "'"), inner_(std::move(inner)) {
    // The capabilities are asked once; a plugin that throws when asked has none.
    if (!contained(who_, [&] { inner_cutting_ = inner_->plane_cutting(); })) inner_cutting_ = nullptr;
    if (!contained(who_, [&] { inner_replay_ = inner_->cut_plan_replay(); })) inner_replay_ = nullptr;
  }

  [[nodiscard]] std::string_view name() const override { return name_; }

  [[nodiscard]] Result<std::vector<Fragment>> fracture(const Mesh& solid, const FractureParams& params) const override {
    std::optional<Result<std::vector<Fragment>>> out;
    if (Status s = contained(who_, [&] { out.emplace(inner_->fracture(solid, params)); }); !s) return s.error();
    if (!*out) return outside_error(out->error());
    if (Status s = check_fracture_output(solid, **out, name_, limits_with_stated_tolerance(volume_tolerance())); !s)
      return fault(s);
    return std::move(*out);
  }

  [[nodiscard]] Result<std::optional<CutPlan>> cut_plan(const Mesh& solid, const FractureParams& params) const override {
    std::optional<Result<std::optional<CutPlan>>> out;
    if (Status s = contained(who_, [&] { out.emplace(inner_->cut_plan(solid, params)); }); !s) return s.error();
    if (!*out) return outside_error(out->error());
    if (**out)
      if (Status s = check_cut_plan(***out); !s)
        return Error{who_ + " returned an invalid cut plan: " + s.error().message, ErrorCause::algorithm_fault};
    return std::move(*out);
  }

  [[nodiscard]] const PlaneCutting* plane_cutting() const override { return inner_cutting_ ? this : nullptr; }

  [[nodiscard]] Result<std::vector<Fragment>> cut_by_planes(const Mesh& solid,
                                                            std::span<const Plane> planes) const override {
    return checked_fragments(solid, [&] { return inner_cutting_->cut_by_planes(solid, planes); });
  }

  [[nodiscard]] const CutPlanReplay* cut_plan_replay() const override { return inner_replay_ ? this : nullptr; }

  [[nodiscard]] Result<std::vector<Fragment>> replay(const Mesh& solid, const CutPlan& plan) const override {
    return checked_fragments(solid, [&] { return inner_replay_->replay(solid, plan); });
  }

  [[nodiscard]] double volume_tolerance() const override {
    double stated = 0.0;
    // A plugin that cannot say is held to round-off; the check clamps what it says.
    if (!contained(who_, [&] { stated = inner_->volume_tolerance(); })) return 0.0;
    return stated;
  }

  [[nodiscard]] bool exact_reference() const override {
    bool exact = false;
    // A plugin that cannot say is measured like any other fracturer.
    if (!contained(who_, [&] { exact = inner_->exact_reference(); })) return false;
    return exact;
  }

 private:
  /// `call`'s fragments of `solid`, contained and checked as fracture's are (round-off volume).
  template <class Call>
  Result<std::vector<Fragment>> checked_fragments(const Mesh& solid, Call&& call) const {
    std::optional<Result<std::vector<Fragment>>> out;
    if (Status s = contained(who_, [&] { out.emplace(call()); }); !s) return s.error();
    if (!*out) return outside_error(out->error());
    if (Status s = check_fracture_output(solid, **out, name_); !s) return fault(s);
    return std::move(*out);
  }

  std::string name_;
  std::string who_;
  std::unique_ptr<Fracturer> inner_;
  const PlaneCutting* inner_cutting_ = nullptr;  // inner_'s, or null
  const CutPlanReplay* inner_replay_ = nullptr;  // inner_'s, or null
};

/// A solver that could not be made: every evaluation is that error.
class RefusedStressSolver final : public StressSolver {
 public:
  RefusedStressSolver(const SupportGraph& graph, Error why) : graph_(graph), why_(std::move(why)) {}
  [[nodiscard]] const SupportGraph& graph() const override { return graph_; }
  [[nodiscard]] Result<StressResult> evaluate(const Loads&) override { return why_; }
  [[nodiscard]] Result<StressResult> reevaluate(const Loads&, const StressResult&, std::span<const int>) override {
    return why_;
  }

 private:
  const SupportGraph& graph_;
  Error why_;
};

class GuardedStressSolver final : public StressSolver {
 public:
  GuardedStressSolver(std::string name, const SupportGraph& graph, std::unique_ptr<StressSolver> inner)
      : name_(std::move(name)), who_("stress model '" + name_ + "'"), graph_(graph), inner_(std::move(inner)) {}

  [[nodiscard]] const SupportGraph& graph() const override { return graph_; }

  [[nodiscard]] Result<StressResult> evaluate(const Loads& loads) override {
    return checked([&] { return inner_->evaluate(loads); });
  }

  [[nodiscard]] Result<StressResult> reevaluate(const Loads& loads, const StressResult& previous,
                                                std::span<const int> touched) override {
    return checked([&] { return inner_->reevaluate(loads, previous, touched); });
  }

 private:
  template <class Call>
  Result<StressResult> checked(Call&& call) {
    std::optional<Result<StressResult>> out;
    if (Status s = contained(who_, [&] { out.emplace(call()); }); !s) return s.error();
    if (!*out) return outside_error(out->error());
    if (Status s = check_stress_output(graph_, **out, name_); !s) return fault(s);
    return std::move(*out);
  }

  std::string name_;
  std::string who_;
  const SupportGraph& graph_;
  std::unique_ptr<StressSolver> inner_;
};

class GuardedStressModel final : public StressModel {
 public:
  GuardedStressModel(std::string name, std::unique_ptr<StressModel> inner)
      : name_(std::move(name)), who_("stress model '" + name_ + "'"), inner_(std::move(inner)) {}

  [[nodiscard]] std::string_view name() const override { return name_; }

  [[nodiscard]] bool driven_by_loads() const override {
    // Unknown (it threw): the pipeline then never skips the solve, which cannot change a result.
    bool driven = false;
    if (!contained(who_, [&] { driven = inner_->driven_by_loads(); })) return false;
    return driven;
  }

  [[nodiscard]] std::unique_ptr<StressModel> exact_cascade_reference() const override {
    // A plugin that throws when asked states no reference; the reference it makes is guarded too.
    std::unique_ptr<StressModel> reference;
    if (!contained(who_, [&] { reference = inner_->exact_cascade_reference(); }) || reference == nullptr) return nullptr;
    std::string name;
    if (!contained(who_, [&] { name = std::string(reference->name()); })) return nullptr;
    return std::make_unique<GuardedStressModel>(std::move(name), std::move(reference));
  }

  [[nodiscard]] std::unique_ptr<StressSolver> make_solver(const SupportGraph& graph,
                                                          const Material& material) const override {
    std::unique_ptr<StressSolver> solver;
    if (Status s = contained(who_ + " making a solver", [&] { solver = inner_->make_solver(graph, material); }); !s)
      return std::make_unique<RefusedStressSolver>(graph, s.error());
    if (solver == nullptr)
      return std::make_unique<RefusedStressSolver>(graph, Error{who_ + " made no solver (a null)", ErrorCause::algorithm_fault});
    return std::make_unique<GuardedStressSolver>(name_, graph, std::move(solver));
  }

 private:
  std::string name_;
  std::string who_;
  std::unique_ptr<StressModel> inner_;
};

/// The factory `inner` of `kind` `name`, guarded: a throw or a null is an error, what it makes is
/// wrapped in `Guarded`.
template <class Plugin, class Guarded>
typename Registry<Plugin>::Factory guarded_factory(const std::string& name, typename Registry<Plugin>::Factory inner) {
  return [name, inner = std::move(inner)](const PluginSettings& settings) -> Result<std::unique_ptr<Plugin>> {
    const std::string who = std::string(plugin_kind<Plugin>) + " '" + name + "'";
    std::optional<Result<std::unique_ptr<Plugin>>> made;
    if (Status s = contained("the factory of " + who, [&] { made.emplace(inner(settings)); }); !s) return s.error();
    if (!*made) return outside_error(made->error());
    if (**made == nullptr) return Error{"the factory of " + who + " returned no object (a null)", ErrorCause::algorithm_fault};
    return std::unique_ptr<Plugin>(std::make_unique<Guarded>(name, std::move(**made)));
  };
}

}  // namespace

std::string one_printable_line(const std::string& text, std::size_t limit) {
  std::string out;
  out.reserve(std::min(text.size(), limit));
  for (const char c : text) {
    if (out.size() >= limit) {
      out += "...";
      break;
    }
    const auto u = static_cast<unsigned char>(c);
    out += (u < 0x20 || u == 0x7f) ? ' ' : c;
  }
  return out;
}

void guard_registrations(Registries& staged) {
  staged.fracturers.wrap_factories([](const std::string& name, FracturerRegistry::Factory f) {
    return guarded_factory<Fracturer, GuardedFracturer>(name, std::move(f));
  });
  staged.stress_models.wrap_factories([](const std::string& name, StressModelRegistry::Factory f) {
    return guarded_factory<StressModel, GuardedStressModel>(name, std::move(f));
  });
}

}  // namespace shatter
