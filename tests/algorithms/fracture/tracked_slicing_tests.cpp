// Deferred attributes (corner_provenance.h) through the slicing kernel: a tracked piece cut again and
// again must resolve to the values the attributes' own formula gives at every corner (UVs affine in
// position, flat face normals), cap faces to their plane's outward normal and the interior material,
// and to the same mesh, to round-off, as slicing with the values carried at every cut.

#include "algorithms/core/corner_provenance.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/random.h"
#include "algorithms/fracture/plane_slice/mesh_slicer.h"
#include "tests/support/attributed_meshes.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace shatter;

namespace {

/// Cuts `start` by `planes` in turn, keeping both sides of every cut (breadth first), tracked by
/// `provenance` when given. Pieces a plane misses are kept whole.
std::vector<Mesh> slice_all(const Mesh& start, const std::vector<Plane>& planes, CornerProvenance* provenance) {
  MeshSlicer slicer;
  std::vector<Mesh> pieces{start};
  for (const Plane& plane : planes) {
    std::vector<Mesh> next;
    for (Mesh& piece : pieces) {
      Mesh below;
      Mesh above;
      const SliceOutcome outcome = slicer.slice(piece, plane, below, above, provenance);
      REQUIRE(outcome != SliceOutcome::failed);
      if (outcome != SliceOutcome::cut) {
        next.push_back(std::move(piece));
        continue;
      }
      next.push_back(std::move(below));
      next.push_back(std::move(above));
    }
    pieces = std::move(next);
  }
  return pieces;
}

/// Planes through points near the centre of the unit sphere, with random normals.
std::vector<Plane> random_planes(int count, std::uint64_t seed) {
  SplitMix64 rng(seed);
  std::vector<Plane> planes;
  for (int i = 0; i < count; ++i) planes.push_back({0.3 * rng.unit_vector(), rng.unit_vector()});
  return planes;
}

Vec3 face_normal(const Mesh& mesh, std::size_t f) {
  const Triangle& t = mesh.triangles[f];
  const Vec3& p0 = mesh.vertices[static_cast<std::size_t>(t[0])];
  return (mesh.vertices[static_cast<std::size_t>(t[1])] - p0).cross(mesh.vertices[static_cast<std::size_t>(t[2])] - p0);
}

}  // namespace

TEST_CASE("tracked slicing: every corner resolves to the affine UVs, face normals and materials",
          "[attributes][provenance]") {
  const Mesh sphere = test::with_affine_attributes(make_sphere(1.0, 24, 12));
  const std::vector<Plane> planes = random_planes(5, 7);
  CornerProvenance provenance(sphere);
  const std::vector<Mesh> tracked = slice_all(provenance.tracked(), planes, &provenance);
  REQUIRE(tracked.size() > planes.size());
  const std::int32_t interior = sphere.attributes.cut.material;
  const int stride = sphere.attributes.layout.stride();
  int caps = 0;
  for (const Mesh& piece : tracked) {
    const Mesh m = *provenance.resolve(Mesh(piece));
    REQUIRE(check_attributes(m, "fragment").ok());
    REQUIRE(m.triangles == piece.triangles);
    REQUIRE(m.vertices == piece.vertices);
    REQUIRE(m.tags == piece.tags);
    REQUIRE(m.attributes.corners.size() == 3 * m.triangles.size() * static_cast<std::size_t>(stride));
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
      const Vec3 n = face_normal(m, f);
      const bool cap = m.tags[f] == FaceTag::cut;
      CHECK(m.attributes.materials[f] == (cap ? interior : 0));
      for (int k = 0; k < 3; ++k) {
        const double* c = m.attributes.corner(f, k);
        const Vec3 normal(c[0], c[1], c[2]);
        // Flat normals: each corner's normal is its face's own direction (a surface piece lies in
        // its source face's plane; a cap in its cut plane, whose normal is stored exactly).
        CHECK(normal.normalized().dot(n.normalized()) == Approx(1.0).margin(1e-9));
        if (cap) continue;
        const Vec3& p = m.vertices[static_cast<std::size_t>(m.triangles[f][static_cast<std::size_t>(k)])];
        for (int set = 0; set < 2; ++set) {
          const Vec2 want = test::affine_uv(p, set);
          CHECK(c[3 + 2 * set] == Approx(want.x()).margin(1e-12));
          CHECK(c[4 + 2 * set] == Approx(want.y()).margin(1e-12));
        }
      }
      caps += cap;
    }
  }
  CHECK(caps > 0);
  // A cap's normal is its plane's, unit length, to round-off.
  for (const Mesh& piece : tracked) {
    const Mesh m = *provenance.resolve(Mesh(piece));
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
      if (m.tags[f] != FaceTag::cut) continue;
      const double* c = m.attributes.corner(f, 0);
      bool on_a_plane = false;
      for (const Plane& plane : planes)
        on_a_plane = on_a_plane || (Vec3(c[0], c[1], c[2]) - plane.normal.normalized()).norm() < 1e-15 ||
                     (Vec3(c[0], c[1], c[2]) + plane.normal.normalized()).norm() < 1e-15;
      CHECK(on_a_plane);
    }
  }
}

TEST_CASE("tracked slicing: the same mesh as carrying the values through every cut", "[attributes][provenance]") {
  const Mesh sphere = test::with_affine_attributes(make_sphere(1.0, 20, 10));
  const std::vector<Plane> planes = random_planes(4, 11);
  CornerProvenance provenance(sphere);
  const std::vector<Mesh> tracked = slice_all(provenance.tracked(), planes, &provenance);
  const std::vector<Mesh> carried = slice_all(sphere, planes, nullptr);
  REQUIRE(tracked.size() == carried.size());
  for (std::size_t i = 0; i < tracked.size(); ++i) {
    const Mesh m = *provenance.resolve(Mesh(tracked[i]));
    const Mesh& want = carried[i];
    REQUIRE(m.vertices == want.vertices);
    REQUIRE(m.triangles == want.triangles);
    REQUIRE(m.tags == want.tags);
    REQUIRE(m.attributes.materials == want.attributes.materials);
    REQUIRE(m.attributes.slots == want.attributes.slots);
    REQUIRE(m.attributes.cut == want.attributes.cut);
    REQUIRE(m.attributes.corners.size() == want.attributes.corners.size());
    double worst = 0.0;
    for (std::size_t v = 0; v < m.attributes.corners.size(); ++v)
      worst = std::max(worst, std::abs(m.attributes.corners[v] - want.attributes.corners[v]));
    CHECK(worst < 1e-13);
  }
}

TEST_CASE("tracked slicing: faces no plane crosses resolve bit for bit", "[attributes][provenance]") {
  const Mesh sphere = test::with_affine_attributes(make_sphere(1.0, 16, 8));
  CornerProvenance provenance(sphere);
  // A plane that misses the sphere keeps it whole: every record is the face itself.
  const std::vector<Mesh> whole = slice_all(provenance.tracked(), {Plane{Vec3(0, 0, 5), Vec3::UnitZ()}}, &provenance);
  REQUIRE(whole.size() == 1);
  const Mesh m = *provenance.resolve(Mesh(whole[0]));
  CHECK(m.attributes == sphere.attributes);
  CHECK(m.triangles == sphere.triangles);
}
