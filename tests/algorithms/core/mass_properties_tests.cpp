#include "algorithms/core/mass_properties.h"
#include "algorithms/core/primitives.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace shatter;

namespace {

constexpr double pi = std::numbers::pi;

/// Tetrahedron with corner `o` and edges a x, b y, c z from it, outward.
Mesh corner_tetrahedron(double a, double b, double c) {
  Mesh mesh;
  mesh.add_vertex({0, 0, 0});
  mesh.add_vertex({a, 0, 0});
  mesh.add_vertex({0, b, 0});
  mesh.add_vertex({0, 0, c});
  mesh.add_triangle(0, 2, 1, FaceTag::surface);
  mesh.add_triangle(0, 1, 3, FaceTag::surface);
  mesh.add_triangle(0, 3, 2, FaceTag::surface);
  mesh.add_triangle(1, 2, 3, FaceTag::surface);
  return mesh;
}

double relative_error(double value, double truth) { return std::abs(value - truth) / std::abs(truth); }

}  // namespace

TEST_CASE("mass: box volume, centroid and inertia match the analytic tensor", "[mass]") {
  const Vec3 size(2.0, 3.0, 5.0), center(0.5, -1.0, 2.0);
  const MassProperties mp = mass_properties(make_box(size, center));
  const double m = 30.0;  // volume, density 1
  CHECK(mp.volume == Approx(m).epsilon(1e-14));
  CHECK((mp.centroid - center).norm() < 1e-13);
  // Solid cuboid: I_xx = m/12 (b^2 + c^2), products of inertia zero.
  Eigen::Matrix3d truth = Eigen::Matrix3d::Zero();
  truth(0, 0) = m / 12.0 * (9.0 + 25.0);
  truth(1, 1) = m / 12.0 * (4.0 + 25.0);
  truth(2, 2) = m / 12.0 * (4.0 + 9.0);
  CHECK((mp.inertia - truth).norm() < 1e-12 * truth.norm());
}

TEST_CASE("mass: a box far from the origin keeps its volume and inertia", "[mass]") {
  const Vec3 center(1e6, -2e6, 3e6);
  const MassProperties mp = mass_properties(make_box(Vec3(1.0, 2.0, 4.0), center));
  CHECK(relative_error(mp.volume, 8.0) < 1e-9);
  CHECK(relative_error(signed_volume(make_box(Vec3(1.0, 2.0, 4.0), center)), 8.0) < 1e-9);
  CHECK((mp.centroid - center).norm() < 1e-9);
  CHECK(relative_error(mp.inertia(2, 2), 8.0 / 12.0 * (1.0 + 4.0)) < 1e-9);
  CHECK(std::abs(mp.inertia(0, 1)) < 1e-9);
}

TEST_CASE("mass: rotated box inertia is R D R^T", "[mass]") {
  const Vec3 size(1.0, 2.0, 3.0);
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxisd(-1.1, Vec3::UnitX())).toRotationMatrix();
  Mesh box = make_box(size);
  const Vec3 shift(3.0, -4.0, 0.5);
  for (Vec3& p : box.vertices) p = rotation * p + shift;
  const double m = 6.0;
  const Eigen::Vector3d d(m / 12 * (4 + 9), m / 12 * (1 + 9), m / 12 * (1 + 4));
  const Eigen::Matrix3d truth = rotation * d.asDiagonal() * rotation.transpose();
  const MassProperties mp = mass_properties(box);
  CHECK(mp.volume == Approx(m).epsilon(1e-13));
  CHECK((mp.centroid - shift).norm() < 1e-13);
  CHECK((mp.inertia - truth).norm() < 1e-12 * truth.norm());
}

TEST_CASE("mass: corner tetrahedron inertia matches the textbook integrals", "[mass]") {
  // Over {x/a + y/b + z/c <= 1, x, y, z >= 0}, by direct integration: V = abc/6, centroid (a, b, c)/4,
  // int x^2 dV = a^3 b c / 60, int x y dV = a^2 b^2 c / 120 (and cyclically).
  const double a = 1.0, b = 2.0, c = 3.0;
  const MassProperties mp = mass_properties(corner_tetrahedron(a, b, c));
  const double volume = a * b * c / 6.0;
  const Vec3 centroid(a / 4, b / 4, c / 4);
  const Vec3 sq(a * a * a * b * c / 60, a * b * b * b * c / 60, a * b * c * c * c / 60);
  const double xy = a * a * b * b * c / 120, yz = a * b * b * c * c / 120, zx = a * a * b * c * c / 120;
  Eigen::Matrix3d second;  // int x x^T dV about the origin
  second << sq.x(), xy, zx, xy, sq.y(), yz, zx, yz, sq.z();
  const Eigen::Matrix3d covariance = second - volume * centroid * centroid.transpose();
  const Eigen::Matrix3d truth = covariance.trace() * Eigen::Matrix3d::Identity() - covariance;
  CHECK(mp.volume == Approx(volume).epsilon(1e-14));
  CHECK((mp.centroid - centroid).norm() < 1e-14);
  CHECK((mp.inertia - truth).norm() < 1e-13 * truth.norm());
  // Spot value: I_xx about the centroid = 3/80 m (b^2 + c^2) for the corner tetrahedron.
  CHECK(mp.inertia(0, 0) == Approx(3.0 / 80.0 * volume * (b * b + c * c)).epsilon(1e-13));
}

TEST_CASE("mass: an inward mesh has negative signed volume", "[mass]") {
  Mesh box = make_box(Vec3(1.0, 1.0, 2.0));
  for (Triangle& t : box.triangles) std::swap(t[1], t[2]);
  CHECK(signed_volume(box) == Approx(-2.0).epsilon(1e-14));
  CHECK(mass_properties(box).volume == Approx(-2.0).epsilon(1e-14));
}

TEST_CASE("mass: polyhedral cylinder, tube, sphere and torus volumes match their closed forms", "[mass]") {
  // A solid swept around z by n planar segments of half-plane cross-section P has the exact volume
  // n sin(2 pi / n) Q, with Q = int_P x dA (the first moment of P about the axis); for a rectangle
  // [0, r] x [0, h] this is the n-gon prism n/2 r^2 sin(2 pi / n) h.
  const double r = 0.7, h = 1.9;
  for (const int n : {3, 4, 7, 32, 100}) {
    const double prism = n / 2.0 * r * r * std::sin(2 * pi / n) * h;
    CHECK(signed_volume(make_cylinder(r, h, n, Vec3(1, 2, 3))) == Approx(prism).epsilon(1e-13));
    const double ri = 0.3;
    const double tube = n / 2.0 * (r * r - ri * ri) * std::sin(2 * pi / n) * h;
    CHECK(signed_volume(make_tube(ri, r, h, n)) == Approx(tube).epsilon(1e-13));
  }
  // UV sphere: P is the half polygon through (r sin(pi j / R), r cos(pi j / R)); as a fan of
  // triangles from the centre, Q = r^3 sin(pi / R) / 3 * sum_{j=1}^{R-1} sin(pi j / R).
  for (const auto& [segments, rings] : {std::pair{3, 2}, {8, 5}, {32, 16}, {64, 33}}) {
    double sum = 0.0;
    for (int j = 1; j < rings; ++j) sum += std::sin(pi * j / rings);
    const double q = r * r * r * std::sin(pi / rings) / 3.0 * sum;
    const double truth = segments * std::sin(2 * pi / segments) * q;
    CHECK(signed_volume(make_sphere(r, segments, rings)) == Approx(truth).epsilon(1e-13));
  }
  // Torus: P is the regular m-gon of circumradius r around (R, 0): Q = R m/2 r^2 sin(2 pi / m).
  const double major = 2.0, minor = 0.5;
  for (const auto& [nm, nn] : {std::pair{3, 3}, {12, 8}, {48, 24}}) {
    const double truth = nm * std::sin(2 * pi / nm) * major * nn / 2.0 * minor * minor * std::sin(2 * pi / nn);
    CHECK(signed_volume(make_torus(major, minor, nm, nn)) == Approx(truth).epsilon(1e-13));
  }
}

TEST_CASE("mass: fine primitives converge to the smooth volumes", "[mass]") {
  // Inscribed n-gons lose a relative (2 pi / n)^2 / 6 of their area: 1e-4 at n = 256.
  CHECK(signed_volume(make_sphere(1.0, 512, 256)) == Approx(4.0 / 3.0 * pi).epsilon(1e-4));
  CHECK(signed_volume(make_cylinder(1.0, 2.0, 1024)) == Approx(2.0 * pi).epsilon(1e-4));
  CHECK(signed_volume(make_torus(2.0, 0.5, 512, 256)) == Approx(2 * pi * pi * 2.0 * 0.25).epsilon(2e-4));
}

TEST_CASE("mass: surface area and tagged area of a box", "[mass]") {
  Mesh box = make_box(Vec3(1.0, 2.0, 3.0));
  CHECK(surface_area(box) == Approx(2 * (2.0 + 6.0 + 3.0)).epsilon(1e-14));
  // Tag the two triangles of the face x = +0.5 (area 2 x 3) as cut.
  double cut_truth = 0.0;
  for (std::size_t f = 0; f < box.triangles.size(); ++f) {
    const Triangle& t = box.triangles[f];
    if (box.vertices[t[0]].x() > 0 && box.vertices[t[1]].x() > 0 && box.vertices[t[2]].x() > 0) {
      box.tags[f] = FaceTag::cut;
      cut_truth = 6.0;
    }
  }
  CHECK(tagged_area(box, FaceTag::cut) == Approx(cut_truth).epsilon(1e-14));
  CHECK(tagged_area(box, FaceTag::surface) == Approx(22.0 - cut_truth).epsilon(1e-14));
}

TEST_CASE("mass: an empty mesh has zero volume and no NaN", "[mass]") {
  const MassProperties mp = mass_properties(Mesh{});
  CHECK(mp.volume == 0.0);
  CHECK(mp.centroid.allFinite());
  CHECK(mp.inertia.allFinite());
}

TEST_CASE("mass: the symmetric second moment summed once per pair of entries is the full sum bit for bit",
          "[mass]") {
  // The full 3 x 3 sum of outer products, written out as the definition, against mass_properties's
  // six entries: the same products in the same order, so the inertia must be equal, not just close.
  const auto full = [](const Mesh& mesh) {
    Aabb box = bounding_box(mesh);
    const Vec3 origin = 0.5 * (box.min + box.max);
    double six_volume = 0.0;
    Vec3 moment24 = Vec3::Zero();
    Eigen::Matrix3d second120 = Eigen::Matrix3d::Zero();
    for (const Triangle& t : mesh.triangles) {
      const Vec3 a = mesh.vertices[t[0]] - origin;
      const Vec3 b = mesh.vertices[t[1]] - origin;
      const Vec3 c = mesh.vertices[t[2]] - origin;
      const double d = a.dot(b.cross(c));
      const Vec3 s = a + b + c;
      six_volume += d;
      moment24 += d * s;
      second120 += d * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
    const double volume = six_volume / 6.0;
    const Vec3 centre = moment24 / (4.0 * six_volume);
    const Eigen::Matrix3d covariance = second120 / 120.0 - volume * centre * centre.transpose();
    Eigen::Matrix3d inertia = covariance.trace() * Eigen::Matrix3d::Identity() - covariance;
    return Eigen::Matrix3d(0.5 * (inertia + inertia.transpose()));
  };
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<Mesh> meshes = {make_torus(1.0, 0.3, 24, 12), make_sphere(0.8, 16, 8), make_box(Vec3(2, 3, 5))};
  Mesh turned = make_box(Vec3(0.4, 0.2, 0.1), Vec3(3.0, -2.0, 7.0));
  for (Vec3& v : turned.vertices) v = turn * v;
  meshes.push_back(std::move(turned));
  for (const Mesh& mesh : meshes) {
    const Eigen::Matrix3d expected = full(mesh);
    const Eigen::Matrix3d got = mass_properties(mesh).inertia;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) CHECK(got(i, j) == expected(i, j));
  }
}

TEST_CASE("mass: volume_centroid is the analytic volume and centroid, and mass_properties' bit for bit",
          "[mass]") {
  // Closed forms first: a box's centre, a corner tetrahedron's a b c / 6 and (a, b, c) / 4.
  const VolumeCentroid box = volume_centroid(make_box(Vec3(2.0, 3.0, 5.0), Vec3(0.5, -1.0, 2.0)));
  CHECK(box.volume == Approx(30.0).epsilon(1e-14));
  CHECK((box.centroid - Vec3(0.5, -1.0, 2.0)).norm() < 1e-13);
  const VolumeCentroid tet = volume_centroid(corner_tetrahedron(1.0, 2.0, 3.0));
  CHECK(tet.volume == Approx(1.0).epsilon(1e-14));
  CHECK((tet.centroid - Vec3(0.25, 0.5, 0.75)).norm() < 1e-14);
  // A fracture cuts a piece again from its centroid and gives the fragment mass_properties' values:
  // the two must agree exactly, or a piece would be cut through another point than before.
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<Mesh> meshes = {make_torus(1.0, 0.3, 24, 12), make_sphere(0.8, 16, 8), make_box(Vec3(2, 3, 5)),
                              make_tube(0.2, 0.5, 1.5, 20), Mesh{}};
  Mesh turned = make_box(Vec3(0.4, 0.2, 0.1), Vec3(3.0, -2.0, 7.0));
  for (Vec3& v : turned.vertices) v = turn * v;
  meshes.push_back(std::move(turned));
  for (const Mesh& mesh : meshes) {
    const MassProperties full = mass_properties(mesh);
    const VolumeCentroid first = volume_centroid(mesh);
    CHECK(first.volume == full.volume);
    CHECK(first.volume == signed_volume(mesh));
    for (int i = 0; i < 3; ++i) CHECK(first.centroid[i] == full.centroid[i]);
  }
}
