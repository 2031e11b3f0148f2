// Attributes through every registered fracturer. A box whose UVs are affine functions of position and
// whose normals are its face normals: every fragment's surface corners must reproduce the affine UVs
// at their positions and the box's face normals, cut faces must carry their own outward normal and the
// interior material. A cylinder with a UV seam must break exactly as it does without attributes, and
// attributes must never change the geometry.

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/solid_check.h"
#include "algorithms/fracture/cgal_clip/cgal_clip_fracturer.h"
#include "tests/support/builtin_registries.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

using namespace shatter;

namespace {

/// The box's UV sets as affine functions of position: set 0 (a x + b, c y + d), set 1 (e z + f, g x + h).
struct AffineUv {
  double a = 0.7, b = 0.1, c = -1.3, d = 0.4, e = 2.1, f = -0.5, g = 0.25, h = 1.0;
  [[nodiscard]] Vec2 uv0(const Vec3& p) const { return {a * p.x() + b, c * p.y() + d}; }
  [[nodiscard]] Vec2 uv1(const Vec3& p) const { return {e * p.z() + f, g * p.x() + h}; }
};

constexpr std::int32_t kBrick = 0;  // the box's only material slot

/// Unit normal of triangle `f` of `mesh` from its positions.
Vec3 geometric_normal(const Mesh& mesh, std::size_t f) {
  const Triangle& t = mesh.triangles[f];
  const Vec3& p0 = mesh.vertices[static_cast<std::size_t>(t[0])];
  return (mesh.vertices[static_cast<std::size_t>(t[1])] - p0).cross(mesh.vertices[static_cast<std::size_t>(t[2])] - p0).normalized();
}

/// The box with a normal and two affine UV sets per corner and one material slot "brick", prepared
/// for fracture.
Mesh attributed_box(const Mesh& box, const AffineUv& uv) {
  Mesh m = box;
  m.attributes.layout.normals = true;
  m.attributes.layout.uv_sets = 2;
  MaterialSlot brick;
  brick.name = "brick";
  brick.base_color = {0.6, 0.2, 0.1, 1.0};
  m.attributes.slots = {brick};
  for (std::size_t f = 0; f < m.triangles.size(); ++f) {
    const Vec3 n = geometric_normal(m, f);
    m.attributes.materials.push_back(kBrick);
    for (const std::int32_t v : m.triangles[f]) {
      const Vec3& p = m.vertices[static_cast<std::size_t>(v)];
      const Vec2 t0 = uv.uv0(p);
      const Vec2 t1 = uv.uv1(p);
      m.attributes.corners.insert(m.attributes.corners.end(), {n.x(), n.y(), n.z(), t0.x(), t0.y(), t1.x(), t1.y()});
    }
  }
  prepare_cut_faces(m);
  return m;
}

/// The cylinder with one UV set u = angle / 2 pi, v = z: the corners at angle 0 of the triangles of the
/// last segment get u = 1 (a seam: one position, two UVs); the axis points get u = 0.5.
Mesh seamed_cylinder(const Mesh& cylinder) {
  Mesh m = cylinder;
  m.attributes.layout.uv_sets = 1;
  for (const Triangle& t : m.triangles) {
    double u[3];
    bool past_half = false;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = m.vertices[static_cast<std::size_t>(t[k])];
      const bool on_axis = p.x() == 0.0 && p.y() == 0.0;
      double angle = std::atan2(p.y(), p.x());
      if (angle < 0.0) angle += 2.0 * std::numbers::pi;
      u[k] = on_axis ? 0.5 : angle / (2.0 * std::numbers::pi);
      past_half = past_half || (!on_axis && u[k] > 0.5);
    }
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = m.vertices[static_cast<std::size_t>(t[k])];
      const bool at_seam = u[k] == 0.0 && !(p.x() == 0.0 && p.y() == 0.0);
      m.attributes.corners.insert(m.attributes.corners.end(), {at_seam && past_half ? 1.0 : u[k], p.z()});
    }
  }
  prepare_cut_faces(m);
  return m;
}

/// The geometry of a fracture: every fragment's positions, triangles and tags.
void check_same_geometry(const std::vector<Fragment>& with, const std::vector<Fragment>& without) {
  REQUIRE(with.size() == without.size());
  for (std::size_t i = 0; i < with.size(); ++i) {
    INFO("fragment " << i);
    CHECK(with[i].mesh.vertices == without[i].mesh.vertices);
    CHECK(with[i].mesh.triangles == without[i].mesh.triangles);
    CHECK(with[i].mesh.tags == without[i].mesh.tags);
    CHECK(without[i].mesh.attributes.empty());
  }
}

/// Checks the attributes of fragments of `box` (attributed_box with `uv`): surface corners carry the
/// affine UVs at their positions and the box's face normal and keep the slot "brick"; cut faces carry
/// their own unit outward normal and the interior slot. Returns the number of cut faces.
int check_box_fragments(const std::vector<Fragment>& fragments, const Mesh& box, const AffineUv& uv) {
  const std::int32_t interior = box.attributes.cut.material;
  // 1e-12 of the UVs' magnitude over the box (|coefficient| x extent + |offset| is at most about 4).
  const double uv_tolerance = 1e-12 * 4.0;
  int cut_faces = 0;
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    const Mesh& m = fragments[i].mesh;
    INFO("fragment " << i);
    const Status s = check_attributes(m, "fragment");
    CHECK(s.ok());
    if (!s) WARN(s.error().message);
    REQUIRE(m.attributes.layout == box.attributes.layout);
    REQUIRE(m.attributes.slots == box.attributes.slots);
    REQUIRE(m.attributes.materials.size() == m.triangles.size());
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
      INFO("triangle " << f);
      const Vec3 g = geometric_normal(m, f);
      if (m.tags[f] == FaceTag::cut) {
        ++cut_faces;
        CHECK(m.attributes.materials[f] == interior);
        for (int k = 0; k < 3; ++k) {
          const double* c = m.attributes.corner(f, k);
          const Vec3 normal(c[0], c[1], c[2]);
          CHECK(std::abs(normal.norm() - 1.0) <= 1e-9);
          CHECK((normal - g).norm() <= 1e-9);
        }
        continue;
      }
      CHECK(m.tags[f] == FaceTag::surface);
      CHECK(m.attributes.materials[f] == kBrick);
      // The box face a surface triangle lies on: the axis its geometric normal points along.
      int axis = 0;
      for (int j = 1; j < 3; ++j)
        if (std::abs(g[j]) > std::abs(g[axis])) axis = j;
      Vec3 face_normal = Vec3::Zero();
      face_normal[axis] = g[axis] > 0.0 ? 1.0 : -1.0;
      for (int k = 0; k < 3; ++k) {
        const Vec3& p = m.vertices[static_cast<std::size_t>(m.triangles[f][k])];
        const double* c = m.attributes.corner(f, k);
        CHECK((Vec3(c[0], c[1], c[2]) - face_normal).norm() <= 1e-12);
        CHECK((Vec2(c[3], c[4]) - uv.uv0(p)).norm() <= uv_tolerance);
        CHECK((Vec2(c[5], c[6]) - uv.uv1(p)).norm() <= uv_tolerance);
      }
    }
  }
  return cut_faces;
}

}  // namespace

TEST_CASE("attributes: every fracturer carries affine UVs, normals and materials exactly", "[attributes][conformance]") {
  const AffineUv uv;
  const Vec3 size(2.0, 3.0, 1.5);
  const Vec3 centre(0.3, -0.2, 0.1);
  const Mesh plain = make_box(size, centre);
  const Mesh box = attributed_box(plain, uv);
  REQUIRE(check_attributes(box, "box").ok());
  REQUIRE(box.attributes.cut.material == 1);

  const Registries r = test::builtin_registries();
  for (const std::string& name : r.fracturers.names()) {
    auto fracturer = r.fracturers.create(name);
    REQUIRE(fracturer.ok());
    for (const int n : {5, 25}) {
      for (const std::uint64_t seed : {3u, 11u}) {
        INFO(name << " at " << n << " fragments, seed " << seed);
        FractureParams params;
        params.fragments = n;
        params.seed = seed;
        Result<std::vector<Fragment>> fragments = (*fracturer)->fracture(box, params);
        REQUIRE(fragments.ok());
        Result<std::vector<Fragment>> geometry = (*fracturer)->fracture(plain, params);
        REQUIRE(geometry.ok());
        check_same_geometry(*fragments, *geometry);
        const int cut_faces = check_box_fragments(*fragments, box, uv);
        if (n > 1 && fragments->size() > 1) CHECK(cut_faces > 0);
      }
    }
  }
}

TEST_CASE("attributes: materials without corner values go through every fracturer", "[attributes][conformance]") {
  Mesh box = make_box(Vec3(2.0, 3.0, 1.5));
  MaterialSlot brick;
  brick.name = "brick";
  box.attributes.slots = {brick};
  box.attributes.materials.assign(box.triangles.size(), 0);
  prepare_cut_faces(box);
  REQUIRE(box.attributes.layout.empty());
  REQUIRE(check_attributes(box, "box").ok());
  const Registries r = test::builtin_registries();
  for (const std::string& name : r.fracturers.names()) {
    INFO(name);
    auto fracturer = r.fracturers.create(name);
    REQUIRE(fracturer.ok());
    FractureParams params;
    params.fragments = 6;
    params.seed = 3;
    const Result<std::vector<Fragment>> fragments = (*fracturer)->fracture(box, params);
    REQUIRE(fragments.ok());
    int cut_faces = 0;
    for (const Fragment& f : *fragments) {
      REQUIRE(check_attributes(f.mesh, name).ok());
      REQUIRE(f.mesh.attributes.materials.size() == f.mesh.triangles.size());
      CHECK(f.mesh.attributes.corners.empty());
      for (std::size_t t = 0; t < f.mesh.triangles.size(); ++t) {
        const bool cut = f.mesh.tags[t] == FaceTag::cut;
        cut_faces += cut ? 1 : 0;
        CHECK(f.mesh.attributes.materials[t] == (cut ? box.attributes.cut.material : 0));
      }
    }
    if (fragments->size() > 1) CHECK(cut_faces > 0);
  }
}

TEST_CASE("attributes: every fracturer refuses a corner value that is not finite and names its triangle",
          "[attributes][conformance]") {
  const Mesh box = attributed_box(make_box(Vec3(2.0, 3.0, 1.5)), AffineUv{});
  const Registries r = test::builtin_registries();
  const std::size_t stride = static_cast<std::size_t>(box.attributes.layout.stride());
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    for (const std::size_t face : {std::size_t{0}, std::size_t{7}, box.triangles.size() - 1}) {
      Mesh m = box;
      // Corner 2's last value (a UV of set 1) of triangle `face`.
      m.attributes.corners[(3 * face + 2) * stride + stride - 1] = bad;
      for (const std::string& name : r.fracturers.names()) {
        INFO(name << ", triangle " << face << ", value " << bad);
        auto fracturer = r.fracturers.create(name);
        REQUIRE(fracturer.ok());
        FractureParams params;
        params.fragments = 5;
        params.seed = 3;
        const Result<std::vector<Fragment>> fragments = (*fracturer)->fracture(m, params);
        REQUIRE_FALSE(fragments.ok());
        CHECK_THAT(fragments.error().message,
                   Catch::StartsWith(name + ": triangle " + std::to_string(face) + " ") &&
                       Catch::Contains("not finite"));
      }
    }
  }
}

TEST_CASE("attributes: no fracturer returns a corner value that is not finite, however large the input's values",
          "[attributes][conformance]") {
  // Values at the largest double, and cut faces whose UVs overflow (a UV scale of 1e-310 m against a
  // box 2 m wide): a fracture refuses, saying so, or every value it returns is finite.
  const Mesh box = attributed_box(make_box(Vec3(2.0, 3.0, 1.5)), AffineUv{});
  Mesh huge_values = box;
  for (double& v : huge_values.attributes.corners) v = std::copysign(std::numeric_limits<double>::max(), v);
  Mesh tiny_scale = box;
  tiny_scale.attributes.cut.uv_scale = 1e-310;
  const Registries r = test::builtin_registries();
  for (const std::string& name : r.fracturers.names()) {
    auto fracturer = r.fracturers.create(name);
    REQUIRE(fracturer.ok());
    for (const bool tiny : {false, true}) {
      INFO(name << (tiny ? ", UV scale 1e-310" : ", values at the largest double"));
      FractureParams params;
      params.fragments = 6;
      params.seed = 11;
      const Result<std::vector<Fragment>> fragments = (*fracturer)->fracture(tiny ? tiny_scale : huge_values, params);
      if (tiny) {
        // Every cut face's UV is out of range: no fracture that cuts may succeed.
        REQUIRE_FALSE(fragments.ok());
      }
      if (!fragments.ok()) {
        CHECK_THAT(fragments.error().message, Catch::StartsWith(name + ": ") && Catch::Contains("overflow"));
        continue;
      }
      for (const Fragment& f : *fragments)
        for (const double v : f.mesh.attributes.corners) REQUIRE(std::isfinite(v));
    }
  }
}

TEST_CASE("attributes: a cylinder with a UV seam breaks as it does without attributes", "[attributes][conformance]") {
  const Mesh plain = make_cylinder(0.5, 1.2, 24);
  const Mesh seamed = seamed_cylinder(plain);
  REQUIRE(check_attributes(seamed, "cylinder").ok());
  REQUIRE(check_solid(seamed, "cylinder", nullptr).ok());
  const Registries r = test::builtin_registries();
  for (const std::string& name : r.fracturers.names()) {
    auto fracturer = r.fracturers.create(name);
    REQUIRE(fracturer.ok());
    for (const int n : {5, 25}) {
      INFO(name << " at " << n << " fragments");
      FractureParams params;
      params.fragments = n;
      params.seed = 7;
      Result<std::vector<Fragment>> with = (*fracturer)->fracture(seamed, params);
      Result<std::vector<Fragment>> without = (*fracturer)->fracture(plain, params);
      REQUIRE(with.ok());
      REQUIRE(without.ok());
      REQUIRE(with->size() == without->size());
      for (std::size_t i = 0; i < with->size(); ++i) {
        INFO("fragment " << i);
        const Fragment& f = (*with)[i];
        const Status closed = check_solid(f.mesh, "fragment", nullptr);
        CHECK(closed.ok());
        if (!closed) WARN(closed.error().message);
        CHECK(check_attributes(f.mesh, "fragment").ok());
        CHECK(f.mass.volume == (*without)[i].mass.volume);
        // Every UV lies in the seamed range: u in [0, 1] on the surface.
        for (std::size_t t = 0; t < f.mesh.triangles.size(); ++t) {
          if (f.mesh.tags[t] != FaceTag::surface) continue;
          for (int k = 0; k < 3; ++k) {
            const double u = f.mesh.attributes.corner(t, k)[0];
            CHECK(u >= -1e-12);
            CHECK(u <= 1.0 + 1e-12);
          }
        }
      }
      check_same_geometry(*with, *without);
    }
  }
}

TEST_CASE("attributes: cgal-clip's exact cells carry the box's attributes", "[attributes][cgal-cells]") {
  const AffineUv uv;
  const Mesh plain = make_box(Vec3(2.0, 3.0, 1.5), Vec3(0.3, -0.2, 0.1));
  const Mesh box = attributed_box(plain, uv);
  // The bisector cells of a few sites inside the box.
  const std::vector<Vec3> sites{{0.9, 1.0, 0.5}, {-0.4, -1.3, 0.6}, {0.5, 0.2, -0.3}, {-0.1, 0.9, 0.2}, {1.0, -1.0, -0.4}};
  std::vector<ConvexCell> cells(sites.size());
  for (std::size_t i = 0; i < sites.size(); ++i)
    for (std::size_t j = 0; j < sites.size(); ++j)
      if (i != j) cells[i].planes.push_back({0.5 * (sites[i] + sites[j]), sites[j] - sites[i]});
  const CgalClipFracturer fracturer;
  Result<std::vector<Fragment>> with = fracturer.fracture_by_cells(box, cells);
  Result<std::vector<Fragment>> without = fracturer.fracture_by_cells(plain, cells);
  REQUIRE(with.ok());
  REQUIRE(without.ok());
  REQUIRE(with->size() == sites.size());
  check_same_geometry(*with, *without);
  CHECK(check_box_fragments(*with, box, uv) > 0);
}
