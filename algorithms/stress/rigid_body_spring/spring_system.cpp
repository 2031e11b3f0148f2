#include "algorithms/stress/rigid_body_spring/spring_system.h"

#include "algorithms/stress/rigid_body_spring/stiffness_pattern.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace shatter {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Vector = Eigen::VectorXd;

}  // namespace

std::vector<double> node_loads(const SupportGraph& graph, const Loads& loads, const Material& material) {
  std::vector<double> f(6 * graph.nodes.size(), 0.0);
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    const Vec3 weight = material.density * graph.nodes[i].volume * loads.gravity;
    for (int k = 0; k < 3; ++k) f[6 * i + static_cast<std::size_t>(k)] = weight[k];
  }
  for (const PointLoad& p : loads.point_loads) {
    const std::size_t i = static_cast<std::size_t>(p.node);
    const Vec3 moment = (p.point - graph.nodes[i].centroid).cross(p.force);
    for (int k = 0; k < 3; ++k) {
      f[6 * i + static_cast<std::size_t>(k)] += p.force[k];
      f[6 * i + 3 + static_cast<std::size_t>(k)] += moment[k];
    }
  }
  return f;
}

SolverReport solve_component(const SupportGraph& graph, std::span<const int> nodes, std::span<const int> bonds,
                             std::span<const double> loads, const Material& material,
                             const SpringSolverSettings& settings, SolverMemory& memory,
                             std::vector<double>& displacements, std::vector<BondForces>& forces,
                             BondStiffnessCache* stiffness) {
  // Local numbering of the free (not anchored) nodes; anchored ones keep -1.
  std::vector<int> local(graph.nodes.size(), -1);
  std::vector<int> free_nodes;
  for (const int v : nodes)
    if (!graph.nodes[static_cast<std::size_t>(v)].anchored) {
      local[static_cast<std::size_t>(v)] = static_cast<int>(free_nodes.size());
      free_nodes.push_back(v);
    }
  const int nf = static_cast<int>(free_nodes.size());
  const int n = 6 * nf;
  SolverReport report;
  report.unknowns = n;

  // Each bond's spring and blocks: the caller's kept ones, or computed here.
  std::vector<BondStiffness> own;
  std::vector<const BondStiffness*> parts(bonds.size());
  if (stiffness != nullptr) {
    stiffness->prepare(bonds);
    for (std::size_t q = 0; q < bonds.size(); ++q) parts[q] = &stiffness->at(bonds[q]);
  } else {
    own.resize(bonds.size());
    for (std::size_t q = 0; q < bonds.size(); ++q) {
      compute_bond_stiffness(graph, bonds[q], material, own[q]);
      parts[q] = &own[q];
    }
  }
  // K in the pattern of the component's bonds (stiffness_pattern.h), summed in bond order.
  std::vector<std::array<int, 2>> ends(bonds.size());
  std::vector<std::array<std::uint64_t, 4>> masks(bonds.size());
  for (std::size_t q = 0; q < bonds.size(); ++q) {
    const Bond& e = graph.bonds[static_cast<std::size_t>(bonds[q])];
    masks[q] = parts[q]->masks;
    ends[q] = {local[static_cast<std::size_t>(e.a)], local[static_cast<std::size_t>(e.b)]};
  }
  StiffnessPattern pattern = build_stiffness_pattern(nf, ends, masks);
  SparseMatrix stiffness_matrix;
  stiffness_matrix.swap(pattern.matrix);  // Eigen's SparseMatrix copies on a move
  for (std::size_t q = 0; q < bonds.size(); ++q)
    for (std::size_t block = 0; block < 4; ++block)
      if (const int p = pattern.bond_pairs[q][block]; p >= 0)
        add_pair_block(stiffness_matrix.valuePtr(), parts[q]->blocks[block], pattern.pairs[static_cast<std::size_t>(p)]);

  Vector f(n), u(n);
  for (int i = 0; i < nf; ++i)
    for (int k = 0; k < 6; ++k) {
      const std::size_t g = 6 * static_cast<std::size_t>(free_nodes[static_cast<std::size_t>(i)]) + static_cast<std::size_t>(k);
      f[6 * i + k] = loads[g];
      u[6 * i + k] = displacements[g];
    }
  if (n > 0 && f.squaredNorm() > 0.0) {
    report = solve_linear(std::move(stiffness_matrix), f, u, settings, memory);
    report.solves = 1;
    report.unknowns = n;
  } else {
    u.setZero();
  }
  for (int i = 0; i < nf; ++i)
    for (int k = 0; k < 6; ++k)
      displacements[6 * static_cast<std::size_t>(free_nodes[static_cast<std::size_t>(i)]) + static_cast<std::size_t>(k)] = u[6 * i + k];
  for (const int v : nodes)
    if (graph.nodes[static_cast<std::size_t>(v)].anchored)
      std::fill_n(displacements.begin() + 6 * static_cast<std::ptrdiff_t>(v), 6, 0.0);

  // Bond forces: the spring forces from the relative motion, expressed in the bond frame.
  for (std::size_t q = 0; q < bonds.size(); ++q) {
    const Bond& e = graph.bonds[static_cast<std::size_t>(bonds[q])];
    forces[static_cast<std::size_t>(bonds[q])] = bond_forces(e, parts[q]->spring, displacements.data() + 6 * static_cast<std::size_t>(e.a),
                                                             displacements.data() + 6 * static_cast<std::size_t>(e.b));
  }
  return report;
}

}  // namespace shatter
