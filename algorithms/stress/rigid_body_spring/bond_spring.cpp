#include "algorithms/stress/rigid_body_spring/bond_spring.h"

#include <algorithm>

namespace shatter {

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

Eigen::Matrix3d skew(const Vec3& r) {
  Eigen::Matrix3d s;
  s << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return s;
}

/// Maps a node's 6 unknowns to the bond's relative motion (delta, phi): +1 for b, -1 for a.
Matrix6 motion_map(const Vec3& lever, double sign) {
  Matrix6 b = Matrix6::Zero();
  b.topLeftCorner<3, 3>() = sign * Eigen::Matrix3d::Identity();
  b.topRightCorner<3, 3>() = -sign * skew(lever);  // theta x r = -[r]x theta
  b.bottomRightCorner<3, 3>() = sign * Eigen::Matrix3d::Identity();
  return b;
}

}  // namespace

BondSpring bond_spring(const SupportGraph& graph, int bond, const Material& m) {
  const Bond& e = graph.bonds[static_cast<std::size_t>(bond)];
  // Second moments are floored at 1e-8 A^2 (a square has A^2 / 12): a sliver contact still resists
  // every rotation a little, so the matrix stays positive definite.
  const double floor = 1e-8 * e.area * e.area;
  const double e_over_l = m.young_modulus / e.length;
  const double g_over_l = m.shear_modulus() / e.length;
  Eigen::Matrix3d frame;  // columns n, axis_1, axis_2
  frame.col(0) = e.normal;
  frame.col(1) = e.axis_1;
  frame.col(2) = e.axis_2;
  const Vec3 translational(e_over_l * e.area, g_over_l * e.area, g_over_l * e.area);
  const Vec3 rotational(g_over_l * std::max(e.polar_moment, 2.0 * floor), e_over_l * std::max(e.moment_1, floor),
                        e_over_l * std::max(e.moment_2, floor));
  BondSpring s;
  s.stiffness = Matrix6::Zero();
  s.stiffness.topLeftCorner<3, 3>() = frame * translational.asDiagonal() * frame.transpose();
  s.stiffness.bottomRightCorner<3, 3>() = frame * rotational.asDiagonal() * frame.transpose();
  s.map_a = motion_map(e.centroid - graph.nodes[static_cast<std::size_t>(e.a)].centroid, -1.0);
  s.map_b = motion_map(e.centroid - graph.nodes[static_cast<std::size_t>(e.b)].centroid, +1.0);
  return s;
}

BondForces bond_forces(const Bond& e, const BondSpring& s, const double* u_a, const double* u_b) {
  Vector6 motion = Vector6::Zero();
  motion += s.map_a * Eigen::Map<const Vector6>(u_a);
  motion += s.map_b * Eigen::Map<const Vector6>(u_b);
  const Vector6 spring = s.stiffness * motion;  // force and moment b receives is minus this
  const Vec3 force = spring.head<3>(), moment = spring.tail<3>();
  BondForces out;
  out.normal = force.dot(e.normal);
  out.shear_1 = force.dot(e.axis_1);
  out.shear_2 = force.dot(e.axis_2);
  out.torsion = moment.dot(e.normal);
  out.moment_1 = moment.dot(e.axis_1);
  out.moment_2 = moment.dot(e.axis_2);
  return out;
}

}  // namespace shatter
