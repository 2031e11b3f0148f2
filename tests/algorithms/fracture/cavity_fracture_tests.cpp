// Solids with cavities: a hollow sphere broken by every fracturer, and a hollow box cut by one plane
// through its cavity, against analytic volumes and areas. A fragment is a volume (an outer shell with
// the cavities inside it): never a cavity shell alone, never of negative volume.

#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/shell_classification.h"
#include "algorithms/core/solid_check.h"
#include "algorithms/core/volume_components.h"
#include "algorithms/fracture/cgal_clip/cgal_clip_fracturer.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "harness/metrics/fracture_metrics.h"
#include "tests/support/builtin_registries.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

using namespace shatter;

namespace {

Mesh reversed(Mesh m) {
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

/// `outer` with `cavity` (given outward) as an inward shell inside it.
Mesh hollow(const Mesh& outer, const Mesh& cavity) {
  Mesh m = outer;
  const Mesh inner = reversed(cavity);
  const auto offset = static_cast<std::int32_t>(m.vertices.size());
  for (const Vec3& v : inner.vertices) m.add_vertex(v);
  for (const Triangle& t : inner.triangles) m.add_triangle(t[0] + offset, t[1] + offset, t[2] + offset, FaceTag::surface);
  return m;
}

/// Every shell of `mesh` faces inward (a cavity shell on its own).
bool only_cavity(const Mesh& mesh) {
  const ShellClassification c = classify_shells(mesh);
  for (const Shell& s : c.shells)
    if (s.outward()) return false;
  return true;
}

}  // namespace

TEST_CASE("cavities: volume_components keeps a cavity with the shell around it", "[cavities]") {
  const Mesh box_in_box = hollow(make_box(Vec3(2, 2, 2)), make_box(Vec3(1, 1, 1)));
  Mesh islands = box_in_box;  // plus a separate box beside it and an island box inside the cavity
  for (const Mesh& extra : {make_box(Vec3(1, 1, 1), Vec3(5, 0, 0)), make_box(Vec3(0.5, 0.5, 0.5))}) {
    const auto offset = static_cast<std::int32_t>(islands.vertices.size());
    for (const Vec3& v : extra.vertices) islands.add_vertex(v);
    for (const Triangle& t : extra.triangles) islands.add_triangle(t[0] + offset, t[1] + offset, t[2] + offset, FaceTag::surface);
  }
  const std::vector<Mesh> one = volume_components(box_in_box);
  REQUIRE(one.size() == 1);
  CHECK(signed_volume(one[0]) == Approx(7.0).epsilon(1e-15));
  const std::vector<Mesh> three = volume_components(islands);
  REQUIRE(three.size() == 3);
  CHECK(signed_volume(three[0]) == Approx(7.0).epsilon(1e-15));
  CHECK(signed_volume(three[1]) == Approx(1.0).epsilon(1e-15));
  CHECK(signed_volume(three[2]) == Approx(0.125).epsilon(1e-15));
}

TEST_CASE("cavities: a hollow box cut through its cavity gives two fragments and an annulus bond", "[cavities]") {
  const Mesh solid = hollow(make_box(Vec3(2, 2, 2)), make_box(Vec3(1, 1, 1)));
  REQUIRE(check_solid(solid, "hollow box", nullptr));
  const MassProperties mass = mass_properties(solid);
  CHECK(mass.volume == Approx(7.0).epsilon(1e-15));
  // Box of sides a, b, c and mass m: I_xx = m (b^2 + c^2) / 12 about its centre; the cavity subtracts.
  CHECK(mass.inertia(0, 0) == Approx(8.0 * 8.0 / 12.0 - 1.0 * 2.0 / 12.0).epsilon(1e-12));

  const Plane plane{Vec3(0.1, -0.2, 0.0), Vec3(0, 0, 1)};  // z = 0: through the cavity
  const std::span<const Plane> planes(&plane, 1);
  for (const bool exact : {false, true}) {
    INFO((exact ? "cgal-clip" : "plane-slice"));
    Result<std::vector<Fragment>> fragments = exact ? CgalClipFracturer().fracture_by_planes(solid, planes)
                                                    : PlaneSliceFracturer().fracture_by_planes(solid, planes);
    REQUIRE(fragments.ok());
    REQUIRE(fragments->size() == 2);
    for (const Fragment& f : *fragments) {
      CHECK(check_solid(f.mesh, "fragment", nullptr));
      CHECK(f.mass.volume == Approx(3.5).epsilon(1e-12));
      // Slab [-1, 1]^2 x [0, 1] less the cavity's half [-0.5, 0.5]^2 x [0, 0.5] (or mirrored).
      const double zc = (4.0 * 0.5 - 0.5 * 0.25) / 3.5;
      CHECK(std::abs(f.mass.centroid.z()) == Approx(zc).epsilon(1e-12));
      CHECK(tagged_area(f.mesh, FaceTag::cut) == Approx(4.0 - 1.0).epsilon(1e-12));  // the annulus cap
    }
    Result<SupportGraph> graph = build_support_graph(std::span<const Fragment>(*fragments), {});
    REQUIRE(graph.ok());
    REQUIRE(graph->bonds.size() == 1);
    CHECK(graph->bonds[0].area == Approx(4.0 - 1.0).epsilon(1e-9));
    // The annulus's second moment about x: square of side 2 less square of side 1 (b h^3 / 12).
    CHECK(graph->bonds[0].moment_1 == Approx((16.0 - 1.0) / 12.0).epsilon(1e-9));
  }
}

TEST_CASE("cavities: every fracturer breaks a hollow sphere into volumes that sum to it", "[cavities][conformance]") {
  // Outer radius 1, cavity radius 0.5, both UV spheres: the polyhedra's volumes are the truth, and
  // they lie within the discretisation of (4/3) pi (1 - 0.125).
  const Mesh outer = make_sphere(1.0, 32, 16);
  const Mesh inner = make_sphere(0.5, 32, 16);
  const Mesh solid = hollow(outer, inner);
  const double polyhedra = signed_volume(outer) - signed_volume(inner);
  const double sphere_shell = 4.0 / 3.0 * std::numbers::pi * (1.0 - 0.125);
  CHECK(std::abs(polyhedra - sphere_shell) / sphere_shell < 0.03);
  const MassProperties mass = mass_properties(solid);
  CHECK(mass.volume == Approx(polyhedra).epsilon(1e-12));
  REQUIRE(check_solid(solid, "hollow sphere", nullptr));

  const Registries r = test::builtin_registries();
  for (const std::string& name : r.fracturers.names()) {
    auto fracturer = r.fracturers.create(name);
    REQUIRE(fracturer.ok());
    for (const int n : {5, 25, 100}) {
      if (name == "cgal-clip" && n > 25) continue;
      INFO(name << " at " << n << " fragments");
      FractureParams params;
      params.fragments = n;
      params.seed = 5;
      Result<std::vector<Fragment>> fragments = (*fracturer)->fracture(solid, params);
      REQUIRE(fragments.ok());
      double sum = 0.0;
      for (std::size_t i = 0; i < fragments->size(); ++i) {
        const Fragment& f = (*fragments)[i];
        INFO("fragment " << i);
        CHECK(f.mass.volume > 0.0);
        CHECK_FALSE(only_cavity(f.mesh));
        const Status s = check_solid(f.mesh, "fragment", nullptr);
        CHECK(s.ok());
        if (!s) WARN(s.error().message);
        sum += f.mass.volume;
      }
      CHECK(std::abs(sum - mass.volume) <= 1e-9 * mass.volume);
      const FractureMetrics m = fracture_metrics(solid, mass, *fragments, n,
                                                 FractureMetricsOptions{.partition_samples = 300, .seed = 3});
      CHECK(m.all_closed);
      CHECK(m.partition_error == 0.0);
    }
  }
}
