// The mesh fingerprint: equal contents give equal fingerprints; the smallest change of a coordinate,
// a corner index, the triangle order or the vertex count gives a different one.

#include "algorithms/core/mesh_fingerprint.h"
#include "algorithms/core/primitives.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <utility>

using namespace shatter;

TEST_CASE("mesh fingerprint: equal meshes agree, any change disagrees", "[mesh-fingerprint]") {
  const Mesh sphere = make_sphere(1.0, 16, 8);
  const Mesh copy = sphere;
  CHECK(mesh_fingerprint(sphere) == mesh_fingerprint(copy));

  Mesh nudged = sphere;
  nudged.vertices[7].y() = std::nextafter(nudged.vertices[7].y(), std::numeric_limits<double>::infinity());
  CHECK(mesh_fingerprint(nudged) != mesh_fingerprint(sphere));

  Mesh flipped = sphere;
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  CHECK(mesh_fingerprint(flipped) != mesh_fingerprint(sphere));

  Mesh reordered = sphere;
  std::swap(reordered.triangles[0], reordered.triangles[1]);
  CHECK(mesh_fingerprint(reordered) != mesh_fingerprint(sphere));

  Mesh extra = sphere;
  extra.vertices.push_back(Vec3::Zero());  // an unused vertex still makes it another mesh
  CHECK(mesh_fingerprint(extra) != mesh_fingerprint(sphere));

  CHECK(mesh_fingerprint(Mesh{}) == mesh_fingerprint(Mesh{}));
  CHECK(mesh_fingerprint(Mesh{}) != mesh_fingerprint(sphere));
}
