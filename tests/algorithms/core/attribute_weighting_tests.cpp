// add_triangle_weighted: corner values as barycentric sums of the source triangle's corners, against
// values that are an affine function of position (so the weighted sum is that function at the point).

#include "algorithms/core/attribute_transfer.h"

#include <catch2/catch.hpp>

using namespace shatter;

namespace {

/// One triangle whose corner values (one UV set) are u = 2 x - y + 0.5, v = 3 y + 1, with two slots.
Mesh affine_triangle() {
  Mesh m;
  m.add_vertex(Vec3(0, 0, 0));
  m.add_vertex(Vec3(1, 0, 0));
  m.add_vertex(Vec3(0, 1, 0));
  m.add_triangle(0, 1, 2, FaceTag::cut);
  m.attributes.layout.uv_sets = 1;
  MaterialSlot a;
  a.name = "a";
  MaterialSlot b;
  b.name = "b";
  m.attributes.slots = {a, b};
  m.attributes.materials = {1};
  for (const Vec3& p : m.vertices) m.attributes.corners.insert(m.attributes.corners.end(), {2 * p.x() - p.y() + 0.5, 3 * p.y() + 1});
  prepare_cut_faces(m);
  return m;
}

}  // namespace

TEST_CASE("attribute transfer: weighted corners are the affine values at the weighted points", "[attributes]") {
  const Mesh src = affine_triangle();
  Mesh dst;
  copy_attribute_frame(src, dst);
  const std::array<CornerWeights, 3> w{{{1.0, 0.0, 0.0}, {0.25, 0.5, 0.25}, {0.0, 0.3, 0.7}}};
  for (const CornerWeights& weights : w) {
    Vec3 p = Vec3::Zero();
    for (int k = 0; k < 3; ++k) p += weights[static_cast<std::size_t>(k)] * src.vertices[static_cast<std::size_t>(k)];
    dst.add_vertex(p);
  }
  add_triangle_weighted(dst, src, 0, 0, 1, 2, w);
  REQUIRE(check_attributes(dst, "dst").ok());
  REQUIRE(dst.triangles.size() == 1);
  CHECK(dst.tags[0] == FaceTag::cut);
  CHECK(dst.attributes.materials[0] == 1);
  for (int k = 0; k < 3; ++k) {
    const Vec3& p = dst.vertices[static_cast<std::size_t>(k)];
    const double* c = dst.attributes.corner(0, k);
    CHECK(c[0] == Approx(2 * p.x() - p.y() + 0.5).margin(1e-15));
    CHECK(c[1] == Approx(3 * p.y() + 1).margin(1e-15));
  }
  // A unit weight copies the corner bit for bit.
  CHECK(dst.attributes.corner(0, 0)[0] == src.attributes.corner(0, 0)[0]);
  CHECK(dst.attributes.corner(0, 0)[1] == src.attributes.corner(0, 0)[1]);
}

TEST_CASE("attribute transfer: a mesh without attributes gets none from weighted corners", "[attributes]") {
  Mesh src;
  src.add_vertex(Vec3(0, 0, 0));
  src.add_vertex(Vec3(1, 0, 0));
  src.add_vertex(Vec3(0, 1, 0));
  src.add_triangle(0, 1, 2, FaceTag::surface);
  Mesh dst = src;
  dst.triangles.clear();
  dst.tags.clear();
  add_triangle_weighted(dst, src, 0, 0, 2, 1, {{{1, 0, 0}, {0, 0, 1}, {0, 1, 0}}});
  CHECK(dst.triangles.size() == 1);
  CHECK(dst.triangles[0] == Triangle{0, 2, 1});
  CHECK(dst.attributes.empty());
  CHECK(dst.attributes.corners.empty());
  CHECK(dst.attributes.materials.empty());
}
