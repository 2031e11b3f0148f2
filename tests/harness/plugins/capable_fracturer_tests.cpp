// Fracturers chosen by capability (harness/plugins/capable_fracturer.h): the plane cutter is the
// preferred fracturer when it cuts by planes, else the first registered one that does; the replayer
// is the exact reference that replays plans; the guard keeps both capabilities of what it wraps.

#include "algorithms/core/primitives.h"
#include "algorithms/registry/registries.h"
#include "harness/plugins/capable_fracturer.h"
#include "harness/plugins/plugin_guard.h"
#include "tests/support/builtin_registries.h"

#include <catch2/catch.hpp>

#include <string>

using namespace shatter;

namespace {

/// The first registered fracturer that cannot cut by planes.
std::string first_without_plane_cutting(const Registries& r) {
  for (const std::string& name : r.fracturers.names())
    if (auto f = r.fracturers.create(name); f && (*f)->plane_cutting() == nullptr) return name;
  return {};
}

/// Every registered fracturer that cuts by planes, in registration order.
std::vector<std::string> plane_cutting_names(const Registries& r) {
  std::vector<std::string> out;
  for (const std::string& name : r.fracturers.names())
    if (auto f = r.fracturers.create(name); f && (*f)->plane_cutting() != nullptr) out.push_back(name);
  return out;
}

}  // namespace

TEST_CASE("capable fracturer: the plane cutter is the preferred one when it cuts, else the first that does",
          "[plugins][capabilities]") {
  Registries r = test::builtin_registries();
  guard_registrations(r);  // as run_cli holds them: the guard must keep the capability
  const std::vector<std::string> cutters = plane_cutting_names(r);
  REQUIRE(cutters.size() >= 2);
  const std::string without = first_without_plane_cutting(r);
  REQUIRE_FALSE(without.empty());

  for (const std::string& preferred : {std::string(), without, std::string("no-such-fracturer")}) {
    auto f = plane_cutter(r.fracturers, preferred);
    REQUIRE(f);
    CHECK((*f)->name() == cutters.front());
    REQUIRE((*f)->plane_cutting() != nullptr);
  }
  auto own = plane_cutter(r.fracturers, cutters.back());
  REQUIRE(own);
  CHECK((*own)->name() == cutters.back());

  // The cut itself, through the guard: a unit cube cut by x = 0 gives two closed halves.
  const Mesh cube = make_box(Vec3(1, 1, 1));
  const Plane x0{Vec3::Zero(), Vec3::UnitX()};
  auto halves = (*own)->plane_cutting()->cut_by_planes(cube, std::span(&x0, 1));
  REQUIRE(halves);
  CHECK(halves->size() == 2);

  Registries none;
  none.fracturers.add(without, "", {}, [&r, without](const PluginSettings&) { return r.fracturers.create(without); });
  CHECK_FALSE(plane_cutter(none.fracturers, without));
}

TEST_CASE("capable fracturer: the replayer is an exact reference that replays cut plans", "[plugins][capabilities]") {
  Registries r = test::builtin_registries();
  guard_registrations(r);
  auto replayer = plan_replayer(r.fracturers);
  REQUIRE(replayer);
  CHECK((*replayer)->exact_reference());
  REQUIRE((*replayer)->cut_plan_replay() != nullptr);
  const Mesh cube = make_box(Vec3(1, 1, 1));
  auto pieces = (*replayer)->cut_plan_replay()->replay(cube, PlaneCuts{{Plane{Vec3::Zero(), Vec3::UnitZ()}}});
  REQUIRE(pieces);
  CHECK(pieces->size() == 2);
}

TEST_CASE("capable stress model: the guard keeps a model's exact cascade reference, guarded", "[plugins][capabilities]") {
  Registries r = test::builtin_registries();
  guard_registrations(r);
  int with = 0;
  for (const std::string& name : r.stress_models.names()) {
    auto m = r.stress_models.create(name);
    REQUIRE(m);
    if (!(*m)->driven_by_loads()) continue;
    INFO(name);
    const std::unique_ptr<StressModel> reference = (*m)->exact_cascade_reference();
    REQUIRE(reference != nullptr);  // every built-in model driven by loads states one
    CHECK(reference->exact_cascade_reference() != nullptr);  // a reference is its own kind's reference
    ++with;
  }
  CHECK(with >= 2);
}
