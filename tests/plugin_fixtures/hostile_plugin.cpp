// A plugin whose algorithms each break one promise of the plugin interface (docs/plugins.md, "What
// the host checks"): the host must turn every one into that algorithm's failed result, with a reason,
// never a crash and never a success. Each fracturer cuts the solid with plane-slice and then spoils
// the result in one way; each stress model spoils connection-count's.

#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "algorithms/registry/plugin_api.h"
#include "algorithms/stress/connection_count/connection_count_model.h"

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace {

using shatter::Fragment;
using Fragments = std::vector<Fragment>;
using Spoil = std::function<shatter::Result<Fragments>(Fragments)>;

class SpoiledFracturer final : public shatter::Fracturer {
 public:
  SpoiledFracturer(std::string name, Spoil spoil, double tolerance = 0.0)
      : name_(std::move(name)), spoil_(std::move(spoil)), tolerance_(tolerance) {}
  [[nodiscard]] std::string_view name() const override { return name_; }
  [[nodiscard]] double volume_tolerance() const override { return tolerance_; }
  [[nodiscard]] shatter::Result<Fragments> fracture(const shatter::Mesh& solid,
                                                    const shatter::FractureParams& params) const override {
    shatter::Result<Fragments> made = shatter::PlaneSliceFracturer().fracture(solid, params);
    if (!made) return made;
    return spoil_(std::move(*made));
  }

 private:
  std::string name_;
  Spoil spoil_;
  double tolerance_;
};

using Corrupt = std::function<void(shatter::StressResult&)>;

class SpoiledSolver final : public shatter::StressSolver {
 public:
  SpoiledSolver(std::unique_ptr<shatter::StressSolver> inner, Corrupt corrupt)
      : inner_(std::move(inner)), corrupt_(std::move(corrupt)) {}
  [[nodiscard]] const shatter::SupportGraph& graph() const override { return inner_->graph(); }
  [[nodiscard]] shatter::Result<shatter::StressResult> evaluate(const shatter::Loads& loads) override {
    return spoiled(inner_->evaluate(loads));
  }
  [[nodiscard]] shatter::Result<shatter::StressResult> reevaluate(const shatter::Loads& loads,
                                                                  const shatter::StressResult& previous,
                                                                  std::span<const int> touched) override {
    return spoiled(inner_->reevaluate(loads, previous, touched));
  }

 private:
  shatter::Result<shatter::StressResult> spoiled(shatter::Result<shatter::StressResult> r) {
    if (r) corrupt_(*r);
    return r;
  }
  std::unique_ptr<shatter::StressSolver> inner_;
  Corrupt corrupt_;
};

class SpoiledModel final : public shatter::StressModel {
 public:
  SpoiledModel(std::string name, Corrupt corrupt, bool null_solver)
      : name_(std::move(name)), corrupt_(std::move(corrupt)), null_solver_(null_solver) {}
  [[nodiscard]] std::string_view name() const override { return name_; }
  [[nodiscard]] std::unique_ptr<shatter::StressSolver> make_solver(const shatter::SupportGraph& graph,
                                                                   const shatter::Material& material) const override {
    if (null_solver_) return nullptr;
    shatter::StressModelRegistry builtin;
    shatter::register_connection_count(builtin);
    auto model = builtin.create("connection-count");
    return std::make_unique<SpoiledSolver>((*model)->make_solver(graph, material), corrupt_);
  }

 private:
  std::string name_;
  Corrupt corrupt_;
  bool null_solver_;
};

void add_fracturer(shatter::Registries& r, const std::string& name, Spoil spoil, double tolerance = 0.0) {
  r.fracturers.add(name, "breaks the plugin contract (test)", {},
                   [name, spoil, tolerance](const shatter::PluginSettings&) -> shatter::Result<std::unique_ptr<shatter::Fracturer>> {
                     return std::unique_ptr<shatter::Fracturer>(std::make_unique<SpoiledFracturer>(name, spoil, tolerance));
                   });
}

/// Fragment 0 scaled about the origin by `factor`, its mass properties its mesh's: the volumes' sum
/// falls short of the input's.
Fragments shrink_first(Fragments f, double factor) {
  for (shatter::Vec3& v : f[0].mesh.vertices) v *= factor;
  f[0].mass = shatter::mass_properties(f[0].mesh);
  return f;
}

void add_model(shatter::Registries& r, const std::string& name, Corrupt corrupt, bool null_solver = false) {
  r.stress_models.add(
      name, "breaks the plugin contract (test)", {},
      [name, corrupt, null_solver](const shatter::PluginSettings&) -> shatter::Result<std::unique_ptr<shatter::StressModel>> {
        return std::unique_ptr<shatter::StressModel>(std::make_unique<SpoiledModel>(name, corrupt, null_solver));
      });
}

void register_hostile(shatter::Registries& r) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  add_fracturer(r, "hostile-index", [](Fragments f) -> shatter::Result<Fragments> {
    f[0].mesh.triangles[0][1] = static_cast<std::int32_t>(f[0].mesh.vertices.size()) + 1000;
    return f;
  });
  add_fracturer(r, "hostile-negative-index", [](Fragments f) -> shatter::Result<Fragments> {
    f.back().mesh.triangles.back()[2] = -7;
    return f;
  });
  add_fracturer(r, "hostile-short-tags", [](Fragments f) -> shatter::Result<Fragments> {
    f[0].mesh.tags.resize(f[0].mesh.tags.size() / 2);
    return f;
  });
  add_fracturer(r, "hostile-tag", [](Fragments f) -> shatter::Result<Fragments> {
    f[0].mesh.tags[0] = static_cast<shatter::FaceTag>(7);
    return f;
  });
  add_fracturer(r, "hostile-nan", [nan](Fragments f) -> shatter::Result<Fragments> {
    f[0].mesh.vertices[0].x() = nan;
    return f;
  });
  add_fracturer(r, "hostile-grows", [](Fragments f) -> shatter::Result<Fragments> {
    for (shatter::Vec3& v : f[0].mesh.vertices) v *= 1.5;
    f[0].mass = shatter::mass_properties(f[0].mesh);
    return f;
  });
  // Approximate methods that state a volume tolerance (Fracturer::volume_tolerance): held to it, at
  // most 0.1; a NaN counts as 0.
  add_fracturer(r, "approximate-within", [](Fragments f) -> shatter::Result<Fragments> { return shrink_first(std::move(f), 0.99); }, 0.05);
  add_fracturer(r, "hostile-overstates", [](Fragments f) -> shatter::Result<Fragments> { return shrink_first(std::move(f), 0.5); }, 5.0);
  add_fracturer(r, "hostile-nan-tolerance", [](Fragments f) -> shatter::Result<Fragments> { return shrink_first(std::move(f), 0.99); }, nan);
  add_fracturer(r, "hostile-drops", [](Fragments f) -> shatter::Result<Fragments> {
    if (f.size() > 1) f.pop_back();
    else f[0].mesh.triangles.pop_back();
    return f;
  });
  add_fracturer(r, "hostile-mass", [](Fragments f) -> shatter::Result<Fragments> {
    f[0].mass.volume *= 2.0;
    return f;
  });
  add_fracturer(r, "hostile-many", [](Fragments f) -> shatter::Result<Fragments> {
    Fragments many(150000, f[0]);
    return many;
  });
  add_fracturer(r, "hostile-open", [](Fragments f) -> shatter::Result<Fragments> {
    f[0].mesh.triangles.pop_back();
    f[0].mesh.tags.pop_back();
    return f;
  });
  add_fracturer(r, "hostile-error", [](Fragments) -> shatter::Result<Fragments> {
    return shatter::Error{"hostile-error refuses\nwith a second line"};
  });
  add_fracturer(r, "hostile-throws-int", [](Fragments) -> shatter::Result<Fragments> { throw 42; });
  add_fracturer(r, "hostile-throws", [](Fragments) -> shatter::Result<Fragments> {
    throw std::runtime_error("hostile-throws threw");
  });
  r.fracturers.add("hostile-null-factory", "its factory returns a null (test)", {},
                   [](const shatter::PluginSettings&) -> shatter::Result<std::unique_ptr<shatter::Fracturer>> {
                     return std::unique_ptr<shatter::Fracturer>();
                   });
  r.fracturers.add("hostile-throwing-factory", "its factory throws an int (test)", {},
                   [](const shatter::PluginSettings&) -> shatter::Result<std::unique_ptr<shatter::Fracturer>> {
                     throw 7;
                   });

  add_model(r, "hostile-nan-stress", [nan](shatter::StressResult& s) {
    if (!s.bonds.empty()) s.bonds[0].utilization = nan;
    s.report.residual = nan;
  });
  add_model(r, "hostile-short-stress", [](shatter::StressResult& s) {
    if (!s.bonds.empty()) s.bonds.pop_back();
  });
  add_model(r, "hostile-cluster", [](shatter::StressResult& s) { s.falling_clusters.push_back({1000000}); });
  add_model(r, "hostile-throws-int-stress", [](shatter::StressResult&) { throw 13; });
  add_model(r, "hostile-null-solver", [](shatter::StressResult&) {}, true);
  r.stress_models.add("hostile-null-model", "its factory returns a null (test)", {},
                      [](const shatter::PluginSettings&) -> shatter::Result<std::unique_ptr<shatter::StressModel>> {
                        return std::unique_ptr<shatter::StressModel>();
                      });
}

}  // namespace

SHATTERBENCH_PLUGIN(register_hostile)
