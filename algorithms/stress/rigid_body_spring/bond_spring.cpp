#include "algorithms/stress/rigid_body_spring/bond_spring.h"

#include <algorithm>

namespace shatter {

namespace {

Eigen::Matrix3d skew(const Vec3& r) {
  Eigen::Matrix3d s;
  s << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return s;
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
  s.translation = frame * translational.asDiagonal() * frame.transpose();
  s.rotation = frame * rotational.asDiagonal() * frame.transpose();
  s.lever_a = e.centroid - graph.nodes[static_cast<std::size_t>(e.a)].centroid;
  s.lever_b = e.centroid - graph.nodes[static_cast<std::size_t>(e.b)].centroid;
  return s;
}

void bond_blocks(const BondSpring& s, std::span<Matrix6, 4> out) {
  // With map = sign [I, -R; 0, I] (R = [lever]x, R^T = -R) and the spring diag(T, Q):
  // map_y^T diag(T, Q) map_x = sign_x sign_y [T, -T R_x; R_y T, Q - R_y T R_x].
  const Eigen::Matrix3d& t = s.translation;
  const Eigen::Matrix3d& q = s.rotation;
  const Eigen::Matrix3d r[2] = {skew(s.lever_a), skew(s.lever_b)};
  const Eigen::Matrix3d tr[2] = {t * r[0], t * r[1]};  // T R_x
  const Eigen::Matrix3d rt[2] = {r[0] * t, r[1] * t};  // R_y T
  for (int x = 0; x < 2; ++x)
    for (int y = 0; y < 2; ++y) {
      const double sign = x == y ? 1.0 : -1.0;  // sign_a = -1, sign_b = +1
      Matrix6& k = out[static_cast<std::size_t>(2 * x + y)];
      k.topLeftCorner<3, 3>() = sign * t;
      k.topRightCorner<3, 3>() = -sign * tr[x];
      k.bottomLeftCorner<3, 3>() = sign * rt[y];
      k.bottomRightCorner<3, 3>() = sign * (q - rt[y] * r[x]);
    }
}

BondForces bond_forces(const Bond& e, const BondSpring& s, const double* u_a, const double* u_b) {
  const Eigen::Map<const Vec3> move_a(u_a), turn_a(u_a + 3), move_b(u_b), turn_b(u_b + 3);
  const Vec3 delta = (move_b + turn_b.cross(s.lever_b)) - (move_a + turn_a.cross(s.lever_a));
  const Vec3 force = s.translation * delta;  // force and moment b receives is minus these
  const Vec3 moment = s.rotation * (turn_b - turn_a);
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
