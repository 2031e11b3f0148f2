#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/mesh_assembly.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/surface_mapping.h"
#include "tests/support/attributed_meshes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

using namespace shatter;

namespace {

const Vec3& corner_position(const Mesh& mesh, std::size_t f, int k) {
  return mesh.vertices[static_cast<std::size_t>(mesh.triangles[f][static_cast<std::size_t>(k)])];
}

/// Largest distance of any corner's UVs from the affine formula at the corner's position.
double affine_uv_error(const Mesh& mesh) {
  double worst = 0.0;
  const AttributeLayout& l = mesh.attributes.layout;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k)
      for (int set = 0; set < l.uv_sets; ++set) {
        const double* uv = mesh.attributes.corner(f, k) + l.uv_offset(set);
        worst = std::max(worst, (Vec2(uv[0], uv[1]) - test::affine_uv(corner_position(mesh, f, k), set)).norm());
      }
  return worst;
}

}  // namespace

TEST_CASE("attributes: the cut-plane basis is orthonormal, right-handed about the canonical normal, and the same for n and -n",
          "[attributes]") {
  for (const Vec3& n : {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 2, 3), Vec3(-3, 0.5, 0.1), Vec3(0, -1, 1e-9),
                        Vec3(1, 1, 1), Vec3(-1e-7, 1e-7, -1)}) {
    INFO(n.transpose());
    const auto e = cut_plane_basis(n);
    const auto f = cut_plane_basis(-n);
    CHECK((e[0] - f[0]).norm() == 0.0);
    CHECK((e[1] - f[1]).norm() == 0.0);
    CHECK(std::abs(e[0].norm() - 1.0) < 1e-14);
    CHECK(std::abs(e[1].norm() - 1.0) < 1e-14);
    CHECK(std::abs(e[0].dot(e[1])) < 1e-14);
    CHECK(std::abs(e[0].dot(n.normalized())) < 1e-14);
    // e1 x e2 is the canonical normal: the one of +-n whose largest component is positive.
    const Vec3 canonical = e[0].cross(e[1]);
    int largest = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(canonical[i]) > std::abs(canonical[largest])) largest = i;
    CHECK(canonical[largest] > 0.0);
    CHECK(std::abs(std::abs(canonical.dot(n.normalized())) - 1.0) < 1e-14);
  }
}

TEST_CASE("attributes: a cut face gets the plane normal, planar UVs, the tangent e1 and the interior material",
          "[attributes]") {
  Mesh mesh = test::with_affine_attributes(make_box(Vec3(1, 1, 1)));
  const std::int32_t interior = mesh.attributes.cut.material;
  REQUIRE(mesh.attributes.slots.size() == 2);
  CHECK(mesh.attributes.slots[1].name == "interior");
  CHECK(interior == 1);
  const std::int32_t a = mesh.add_vertex(Vec3(0.1, 0.2, 0.3));
  const std::int32_t b = mesh.add_vertex(Vec3(0.4, 0.2, 0.3));
  const std::int32_t c = mesh.add_vertex(Vec3(0.1, 0.5, 0.3));
  const Vec3 normal(0, 0, -2);  // any length
  add_cut_triangle(mesh, a, b, c, normal);
  const std::size_t f = mesh.triangles.size() - 1;
  CHECK(mesh.tags[f] == FaceTag::cut);
  CHECK(mesh.attributes.materials[f] == interior);
  REQUIRE(check_attributes(mesh, "mesh").ok());
  const AttributeLayout& l = mesh.attributes.layout;
  const auto e = cut_plane_basis(normal);
  for (int k = 0; k < 3; ++k) {
    const double* v = mesh.attributes.corner(f, k);
    CHECK(Vec3(v[0], v[1], v[2]).isApprox(Vec3(0, 0, -1), 0.0));
    const Vec3& p = corner_position(mesh, f, k);
    for (int set = 0; set < l.uv_sets; ++set) {
      const double* uv = v + l.uv_offset(set);
      CHECK(uv[0] == Approx(p.dot(e[0]) / 0.5).margin(1e-15));
      CHECK(uv[1] == Approx(p.dot(e[1]) / 0.5).margin(1e-15));
    }
    const double* t = v + l.tangent_offset();
    CHECK((Vec3(t[0], t[1], t[2]) - e[0]).norm() < 1e-15);
    // The face's normal is -z, the canonical +z: handedness -1, so bitangent = n x t * w = e2.
    CHECK(t[3] == -1.0);
    CHECK((Vec3(0, 0, -1).cross(e[0]) * t[3] - e[1]).norm() < 1e-15);
  }
}

TEST_CASE("attributes: a cut-face dressing reversed is the dressing of the negated normal, value for value",
          "[attributes]") {
  const Mesh box = make_box(Vec3(2.0, 1.0, 0.5), Vec3(0.3, -0.2, 0.1));
  const std::vector<AttributeLayout> layouts{{true, 1, true}, {true, 0, false}, {false, 2, false}, {true, 3, true}};
  for (const AttributeLayout& layout : layouts) {
    const std::size_t face_values = 3 * static_cast<std::size_t>(layout.stride());
    for (const Vec3& n : {Vec3(0, 0, 1), Vec3(0, 0, -3), Vec3(1, 2, 3), Vec3(-3, 0.5, 0.1), Vec3(0, -1, 1e-9)}) {
      INFO("stride " << layout.stride() << ", normal " << n.transpose());
      const PlanarDressing along(layout, n, 0.7);
      const PlanarDressing against(layout, -n, 0.7);
      const PlanarDressing reversed = along.reversed();
      // Every face of the box, one at a time and as one run: the same values, bit for bit.
      std::vector<double> want(box.triangles.size() * face_values);
      std::vector<double> got_face(want.size());
      std::vector<double> got_run(want.size());
      for (std::size_t f = 0; f < box.triangles.size(); ++f) {
        against.write(corner_position(box, f, 0), corner_position(box, f, 1), corner_position(box, f, 2),
                      want.data() + f * face_values);
        reversed.write(corner_position(box, f, 0), corner_position(box, f, 1), corner_position(box, f, 2),
                       got_face.data() + f * face_values);
      }
      reversed.write_faces(box, 0, box.triangles.size(), got_run.data());
      CHECK(got_face == want);
      CHECK(got_run == want);
      // And reversing twice gives the dressing back.
      std::vector<double> once(face_values);
      std::vector<double> twice(face_values);
      along.write(corner_position(box, 0, 0), corner_position(box, 0, 1), corner_position(box, 0, 2), once.data());
      reversed.reversed().write(corner_position(box, 0, 0), corner_position(box, 0, 1), corner_position(box, 0, 2),
                                twice.data());
      CHECK(twice == once);
    }
  }
}

TEST_CASE("attributes: a corner mixed at parameter t is the linear interpolation, exactly for affine UVs", "[attributes]") {
  const Mesh src = test::with_affine_attributes(make_box(Vec3(2, 1, 3)));
  Mesh dst;
  copy_attribute_frame(src, dst);
  dst.vertices = src.vertices;
  for (std::size_t f = 0; f < src.triangles.size(); ++f) {
    const Triangle& t = src.triangles[f];
    const double s = 0.1 + 0.8 * static_cast<double>(f) / static_cast<double>(src.triangles.size());
    const Vec3 x = corner_position(src, f, 0) + s * (corner_position(src, f, 1) - corner_position(src, f, 0));
    const std::int32_t xi = dst.add_vertex(x);
    add_triangle_mixed(dst, src, f, t[0], xi, t[2], {CornerMix{0, 0, 0.0}, CornerMix{0, 1, s}, CornerMix{2, 2, 0.0}});
  }
  REQUIRE(check_attributes(dst, "dst").ok());
  CHECK(affine_uv_error(dst) < 1e-15);
  CHECK(dst.attributes.materials == std::vector<std::int32_t>(src.triangles.size(), 0));
}

TEST_CASE("attributes: flips, reversal, soups and joins keep each corner's values with its vertex", "[attributes]") {
  const Mesh box = test::with_affine_attributes(make_box(Vec3(1, 2, 1), Vec3(0.3, 0, 0)));
  CHECK(affine_uv_error(box) < 1e-15);
  CHECK(affine_uv_error(reversed_mesh(box)) < 1e-15);
  CHECK(affine_uv_error(triangle_soup(box)) < 1e-15);
  Mesh joined = box;
  append_mesh(joined, test::with_affine_attributes(make_box(Vec3(1, 1, 1), Vec3(5, 0, 0))));
  REQUIRE(check_attributes(joined, "joined").ok());
  CHECK(affine_uv_error(joined) < 1e-15);
  // validate_solid turns an inside-out mesh outward, corners with it.
  Mesh inverted = reversed_mesh(box);
  REQUIRE(validate_solid(inverted, "inverted").ok());
  CHECK(inverted.triangles == box.triangles);
  CHECK(inverted.attributes.corners == box.attributes.corners);
  // keep_triangles drops faces with their values.
  Mesh kept = box;
  std::vector<std::uint8_t> keep(box.triangles.size(), 0);
  for (std::size_t f = 0; f < keep.size(); f += 3) keep[f] = 1;
  keep_triangles(kept, keep);
  REQUIRE(check_attributes(kept, "kept").ok());
  CHECK(kept.triangles.size() == (box.triangles.size() + 2) / 3);
  CHECK(affine_uv_error(kept) < 1e-15);
}

TEST_CASE("attributes: a repaired surface takes the input's values where it lies on it, and repair faces the planar rule",
          "[attributes]") {
  // The "repaired" mesh: the same box re-triangulated as a soup of split triangles (each cut at its
  // first edge's midpoint), plus one face tagged as a repair face.
  const Mesh input = test::with_affine_attributes(make_box(Vec3(1, 1, 1)));
  Mesh repaired;
  repaired.vertices = input.vertices;
  for (const Triangle& t : input.triangles) {
    const std::int32_t m =
        repaired.add_vertex(0.5 * (input.vertices[static_cast<std::size_t>(t[0])] + input.vertices[static_cast<std::size_t>(t[1])]));
    repaired.add_triangle(t[0], m, t[2], FaceTag::surface);
    repaired.add_triangle(m, t[1], t[2], FaceTag::surface);
  }
  repaired.tags.back() = FaceTag::repair;
  transfer_attributes(input, repaired);
  REQUIRE(check_attributes(repaired, "repaired").ok());
  CHECK(repaired.attributes.slots == input.attributes.slots);
  const std::size_t last = repaired.triangles.size() - 1;
  Mesh surface_only = repaired;
  std::vector<std::uint8_t> keep(repaired.triangles.size(), 1);
  keep[last] = 0;
  keep_triangles(surface_only, keep);
  CHECK(affine_uv_error(surface_only) < 1e-14);
  // The repair face: its own normal, planar UVs at the cut-face scale, the material around it.
  const Vec3 n = (corner_position(repaired, last, 1) - corner_position(repaired, last, 0))
                     .cross(corner_position(repaired, last, 2) - corner_position(repaired, last, 0))
                     .normalized();
  const double* v = repaired.attributes.corner(last, 2);
  CHECK((Vec3(v[0], v[1], v[2]) - n).norm() < 1e-15);
  CHECK(v[3] == Approx(cut_face_uv(corner_position(repaired, last, 2), n, 0.5).x()).margin(1e-15));
  CHECK(repaired.attributes.materials[last] == 0);
}

TEST_CASE("attributes: inconsistent attributes are refused with the triangle named", "[attributes]") {
  const Mesh good = test::with_affine_attributes(make_box(Vec3(1, 1, 1)));
  REQUIRE(check_attributes(good, "m").ok());
  Mesh m = good;
  m.attributes.corners.pop_back();
  CHECK_FALSE(check_attributes(m, "m").ok());
  m = good;
  m.attributes.corners[3] = std::nan("");
  const Status nan = check_attributes(m, "m");
  REQUIRE_FALSE(nan.ok());
  CHECK(nan.error().message.find("triangle 0") != std::string::npos);
  m = good;
  m.attributes.materials[5] = 7;
  const Status material = check_attributes(m, "m");
  REQUIRE_FALSE(material.ok());
  CHECK(material.error().message.find("triangle 5") != std::string::npos);
  m = good;
  m.attributes.cut = CutFaceStyle{};
  CHECK_FALSE(check_attributes(m, "m").ok());
  m = good;
  m.attributes.layout.normals = false;
  CHECK_FALSE(check_attributes(m, "m").ok());
  // Per-face entries without slots are attributes (not an empty set), and not valid ones.
  Mesh entries_only = make_box(Vec3(1, 1, 1));
  entries_only.attributes.materials.assign(entries_only.triangles.size(), 0);
  CHECK_FALSE(entries_only.attributes.empty());
  CHECK_FALSE(check_attributes(entries_only, "m").ok());
  // A mesh without attributes has nothing to check, and readying it adds nothing.
  Mesh plain = make_box(Vec3(1, 1, 1));
  prepare_cut_faces(plain);
  CHECK(plain.attributes.empty());
  CHECK(check_attributes(plain, "plain").ok());
}

TEST_CASE("attributes: a fracture's values are bounded by the solid's when its values and size against the UV scale are",
          "[attributes]") {
  const Mesh good = test::with_affine_attributes(make_box(Vec3(1, 1, 1)));
  CHECK(fracture_attributes_bounded(good));
  constexpr double largest = std::numeric_limits<double>::max();
  Mesh m = good;
  m.attributes.corners[4] = -largest / 4.0;  // at the bound
  CHECK(fracture_attributes_bounded(m));
  m.attributes.corners[4] = std::nextafter(-largest / 4.0, -largest);
  CHECK_FALSE(fracture_attributes_bounded(m));
  m.attributes.corners[4] = std::nan("");
  CHECK_FALSE(fracture_attributes_bounded(m));
  m.attributes.corners[4] = std::numeric_limits<double>::infinity();
  CHECK_FALSE(fracture_attributes_bounded(m));
  // The box reaches 0.5 m from the origin: 0.5 / scale must stay within a sixteenth of the largest double.
  m = good;
  m.attributes.cut.uv_scale = 0.5 / (largest / 16.0);
  CHECK(fracture_attributes_bounded(m));
  m.attributes.cut.uv_scale = 1e-310;
  CHECK_FALSE(fracture_attributes_bounded(m));
  // The positions' bound alone: the same answers for the scale, whatever the values.
  m.attributes.corners[4] = std::nan("");
  CHECK_FALSE(cut_face_values_bounded(m));
  m.attributes.cut.uv_scale = 0.5 / (largest / 16.0);
  CHECK(cut_face_values_bounded(m));
}

TEST_CASE("attributes: a finite tally copies every value exactly and finds one that is not finite anywhere",
          "[attributes]") {
  constexpr double inf = std::numeric_limits<double>::infinity();
  // Lengths around the 8 lanes and the vector widths, each offender at every position.
  for (std::size_t count = 0; count <= 41; ++count) {
    std::vector<double> from(count);
    for (std::size_t i = 0; i < count; ++i)  // magnitudes from 2^-800 to 2^840, both signs
      from[i] = (i % 3 == 0 ? -1.0 : 1.0) * std::ldexp(1.0 + 0.1 * static_cast<double>(i), 40 * static_cast<int>(i) - 800);
    from.push_back(std::numeric_limits<double>::max());  // the largest finite value, in every copy
    const std::size_t n = from.size();
    FiniteTally clean;
    std::vector<double> to(n, 0.0);
    clean.copy(from.data(), n, to.data());
    CHECK(to == from);
    CHECK(clean.all_finite());
    FiniteTally added;
    added.add(from.data(), n);
    CHECK(added.all_finite());
    for (std::size_t at = 0; at < n; ++at)
      for (const double bad : {inf, -inf, std::nan("")}) {
        std::vector<double> values = from;
        values[at] = bad;
        FiniteTally copied;
        copied.copy(values.data(), n, to.data());
        CHECK_FALSE(copied.all_finite());
        CHECK((std::isnan(bad) ? std::isnan(to[at]) : to[at] == bad));
        FiniteTally tallied;
        tallied.add(values.data(), n);
        CHECK_FALSE(tallied.all_finite());
        // A tally stays failed whatever comes after.
        copied.copy(from.data(), n, to.data());
        CHECK_FALSE(copied.all_finite());
      }
  }
}

TEST_CASE("attributes: box mapping gives face normals, UVs of right and up over the scale, and a tangent along +u",
          "[attributes]") {
  Mesh box = make_box(Vec3(2, 3, 4));
  MaterialSlot brick;
  brick.name = "brick";
  apply_box_mapping(box, 0.25, brick);
  prepare_cut_faces(box);
  REQUIRE(check_attributes(box, "box").ok());
  CHECK(box.attributes.cut.uv_scale == 4.0);  // the largest side
  const AttributeLayout& l = box.attributes.layout;
  for (std::size_t f = 0; f < box.triangles.size(); ++f) {
    const Vec3 n = (corner_position(box, f, 1) - corner_position(box, f, 0))
                       .cross(corner_position(box, f, 2) - corner_position(box, f, 0))
                       .normalized();
    // The face's axis and the directions right and up seen from outside.
    int axis = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(n[i]) > std::abs(n[axis])) axis = i;
    const Vec3 up = axis == 2 ? Vec3::UnitY() : Vec3::UnitZ();
    const Vec3 right = up.cross(n);
    for (int k = 0; k < 3; ++k) {
      const double* v = box.attributes.corner(f, k);
      CHECK((Vec3(v[0], v[1], v[2]) - n).norm() < 1e-15);
      const Vec3& p = corner_position(box, f, k);
      CHECK(v[l.uv_offset(0)] == Approx(p.dot(right) / 0.25).margin(1e-14));
      CHECK(v[l.uv_offset(0) + 1] == Approx(p.dot(up) / 0.25).margin(1e-14));
      const double* t = v + l.tangent_offset();
      CHECK((Vec3(t[0], t[1], t[2]) - right).norm() < 1e-15);
      CHECK((n.cross(Vec3(t[0], t[1], t[2])) * t[3] - up).norm() < 1e-15);
    }
  }
}
