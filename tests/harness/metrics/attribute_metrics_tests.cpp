#include "algorithms/core/primitives.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "harness/metrics/attribute_metrics.h"
#include "harness/metrics/fracture_acceptance.h"
#include "tests/support/attributed_meshes.h"

#include <catch2/catch.hpp>

using namespace shatter;

namespace {

std::vector<Fragment> slice(const Mesh& mesh, int n) {
  FractureParams params;
  params.fragments = n;
  params.seed = 3;
  Result<std::vector<Fragment>> out = PlaneSliceFracturer().fracture(mesh, params);
  REQUIRE(out.ok());
  return std::move(*out);
}

}  // namespace

TEST_CASE("attribute metrics: exact interpolation reads as round-off, a wrong corner or material as an error",
          "[attribute-metrics]") {
  const Mesh box = test::with_affine_attributes(make_box(Vec3(1, 2, 0.5)));
  std::vector<Fragment> fragments = slice(box, 12);
  const AttributeMetrics good = attribute_metrics(box, fragments);
  REQUIRE(good.measured);
  CHECK(good.samples == 1000);
  CHECK(good.uv_error < 1e-13);
  CHECK(good.normal_error < 1e-13);
  CHECK(good.cap_normal_error < 1e-12);
  CHECK(good.material_errors == 0);
  CHECK(failed_attribute_checks(good).empty());

  // Moving every UV of one fragment's surface faces by 0.01 must show (its area gets samples).
  std::vector<Fragment> shifted = fragments;
  Mesh& m = shifted[0].mesh;
  const AttributeLayout& l = m.attributes.layout;
  for (std::size_t f = 0; f < m.triangles.size(); ++f)
    if (m.tags[f] == FaceTag::surface)
      for (int k = 0; k < 3; ++k) m.attributes.corners[(3 * f + static_cast<std::size_t>(k)) * l.stride() + l.uv_offset(0)] += 0.01;
  const AttributeMetrics bad = attribute_metrics(box, shifted);
  CHECK(bad.uv_error == Approx(0.01).epsilon(1e-9));
  CHECK_FALSE(failed_attribute_checks(bad).empty());

  // A cut face in the surface material, and a surface face in the interior one.
  std::vector<Fragment> swapped = fragments;
  Mesh& s = swapped[1].mesh;
  int cut = 0, surface = 0;
  for (std::size_t f = 0; f < s.triangles.size(); ++f) {
    if (s.tags[f] == FaceTag::cut && cut++ == 0) s.attributes.materials[f] = 0;
    if (s.tags[f] == FaceTag::surface && surface++ == 0) s.attributes.materials[f] = s.attributes.cut.material;
  }
  CHECK(attribute_metrics(box, swapped).material_errors == 2);

  // A cap normal off its plane.
  std::vector<Fragment> tilted = fragments;
  Mesh& t = tilted[2].mesh;
  for (std::size_t f = 0; f < t.triangles.size(); ++f)
    if (t.tags[f] == FaceTag::cut) {
      t.attributes.corners[3 * f * l.stride()] += 0.1;
      break;
    }
  CHECK(attribute_metrics(box, tilted).cap_normal_error > 1e-3);

  // Nothing to measure without attributes.
  const Mesh plain = make_box(Vec3(1, 2, 0.5));
  const AttributeMetrics none = attribute_metrics(plain, slice(plain, 4));
  CHECK_FALSE(none.measured);
  CHECK(failed_attribute_checks(none).empty());
}
