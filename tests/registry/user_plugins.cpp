#include "tests/registry/user_plugins.h"

#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"

#include <memory>

namespace shatter::test {
namespace {

/// n - 1 planes normal to `axis`, evenly spaced inside the solid's bounding box.
class ParallelPlanesFracturer final : public Fracturer {
 public:
  explicit ParallelPlanesFracturer(int axis) : axis_(axis) {}
  [[nodiscard]] std::string_view name() const override { return "parallel-planes"; }
  [[nodiscard]] Result<std::vector<Fragment>> fracture(const Mesh& solid, const FractureParams& params) const override {
    return PlaneSliceFracturer().fracture_by_planes(solid, planes(solid, params.fragments));
  }
  [[nodiscard]] Result<std::optional<CutPlan>> cut_plan(const Mesh& solid,
                                                        const FractureParams& params) const override {
    return std::optional<CutPlan>(PlaneCuts{planes(solid, params.fragments)});
  }

 private:
  [[nodiscard]] std::vector<Plane> planes(const Mesh& solid, int fragments) const {
    const Aabb box = bounding_box(solid);
    std::vector<Plane> out;
    for (int i = 1; i < fragments; ++i) {
      Plane p;
      p.point = box.min + (box.max - box.min) * (static_cast<double>(i) / fragments);
      p.normal = Vec3::Unit(axis_);
      out.push_back(p);
    }
    return out;
  }
  int axis_;
};

/// Von Mises with its utilizations scaled: a solver of the built-in model whose results it rescales.
class ScaledSolver final : public StressSolver {
 public:
  ScaledSolver(std::unique_ptr<StressSolver> inner, double factor) : inner_(std::move(inner)), factor_(factor) {}
  [[nodiscard]] const SupportGraph& graph() const override { return inner_->graph(); }
  [[nodiscard]] Result<StressResult> evaluate(const Loads& loads) override { return scaled(inner_->evaluate(loads)); }
  [[nodiscard]] Result<StressResult> reevaluate(const Loads& loads, const StressResult& previous,
                                                std::span<const int> touched) override {
    return scaled(inner_->reevaluate(loads, previous, touched));
  }

 private:
  [[nodiscard]] Result<StressResult> scaled(Result<StressResult> r) const {
    if (r)
      for (BondStress& b : r->bonds) b.utilization *= factor_;
    return r;
  }
  std::unique_ptr<StressSolver> inner_;
  double factor_;
};

class ScaledVonMisesModel final : public StressModel {
 public:
  explicit ScaledVonMisesModel(double factor) : factor_(factor) {}
  [[nodiscard]] std::string_view name() const override { return "scaled-von-mises"; }
  [[nodiscard]] std::unique_ptr<StressSolver> make_solver(const SupportGraph& graph,
                                                          const Material& material) const override {
    return std::make_unique<ScaledSolver>(inner_.make_solver(graph, material), factor_);
  }

 private:
  StrengthCriterionModel inner_{Criterion::von_mises};
  double factor_;
};

}  // namespace

void register_parallel_planes(FracturerRegistry& registry) {
  std::vector<SettingDoc> docs = {{"axis", "", "0", "[0, 2]", "normal of the planes: 0 x, 1 y, 2 z", {}}};
  registry.add("parallel-planes", "n - 1 evenly spaced parallel planes (a test plugin)", docs,
               [docs](const PluginSettings& settings) -> Result<std::unique_ptr<Fracturer>> {
                 const SettingsReader r("parallel-planes", settings, docs);
                 int axis = 0;
                 if (Status s = r.check_keys(); !s) return s.error();
                 if (Status s = r.integer("axis", 0, 2, axis); !s) return s.error();
                 return std::unique_ptr<Fracturer>(std::make_unique<ParallelPlanesFracturer>(axis));
               });
}

void register_scaled_von_mises(StressModelRegistry& registry) {
  std::vector<SettingDoc> docs = {{"factor", "", "1", "(0, 1000]", "multiplies every utilization", {}}};
  registry.add("scaled-von-mises", "von Mises with scaled utilizations (a test plugin)", docs,
               [docs](const PluginSettings& settings) -> Result<std::unique_ptr<StressModel>> {
                 const SettingsReader r("scaled-von-mises", settings, docs);
                 double factor = 1.0;
                 if (Status s = r.check_keys(); !s) return s.error();
                 if (Status s = r.number_above("factor", 0.0, 1000.0, factor); !s) return s.error();
                 return std::unique_ptr<StressModel>(std::make_unique<ScaledVonMisesModel>(factor));
               });
}

}  // namespace shatter::test
