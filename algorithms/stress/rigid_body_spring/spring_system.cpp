#include "algorithms/stress/rigid_body_spring/spring_system.h"

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
                             const SpringSolverSettings& settings, std::vector<double>& displacements,
                             std::vector<BondForces>& forces) {
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

  // Column pattern: node i's columns hold the 6 rows of i and of every free neighbour, sorted.
  std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(nf));
  for (int i = 0; i < nf; ++i) neighbours[static_cast<std::size_t>(i)].push_back(i);
  for (const int bi : bonds) {
    const Bond& e = graph.bonds[static_cast<std::size_t>(bi)];
    const int la = local[static_cast<std::size_t>(e.a)], lb = local[static_cast<std::size_t>(e.b)];
    if (la >= 0 && lb >= 0) {
      neighbours[static_cast<std::size_t>(la)].push_back(lb);
      neighbours[static_cast<std::size_t>(lb)].push_back(la);
    }
  }
  std::vector<int> outer(static_cast<std::size_t>(n) + 1, 0);
  for (int i = 0; i < nf; ++i) {
    auto& list = neighbours[static_cast<std::size_t>(i)];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    for (int k = 0; k < 6; ++k) outer[static_cast<std::size_t>(6 * i + k + 1)] = 6 * static_cast<int>(list.size());
  }
  for (int c = 0; c < n; ++c) outer[static_cast<std::size_t>(c + 1)] += outer[static_cast<std::size_t>(c)];
  SparseMatrix stiffness(n, n);
  stiffness.resizeNonZeros(outer.back());
  std::copy(outer.begin(), outer.end(), stiffness.outerIndexPtr());
  int* inner = stiffness.innerIndexPtr();
  double* value = stiffness.valuePtr();
  std::fill(value, value + outer.back(), 0.0);
  for (int i = 0; i < nf; ++i)
    for (int k = 0; k < 6; ++k) {
      int at = outer[static_cast<std::size_t>(6 * i + k)];
      for (const int j : neighbours[static_cast<std::size_t>(i)])
        for (int r = 0; r < 6; ++r) inner[at++] = 6 * j + r;
    }
  // Adds a 6 x 6 block at (row node j, column node i).
  auto add_block = [&](int j, int i, const Matrix6& block) {
    const auto& list = neighbours[static_cast<std::size_t>(i)];
    const int slot = static_cast<int>(std::lower_bound(list.begin(), list.end(), j) - list.begin());
    for (int k = 0; k < 6; ++k) {
      double* column = value + outer[static_cast<std::size_t>(6 * i + k)] + 6 * slot;
      for (int r = 0; r < 6; ++r) column[r] += block(r, k);
    }
  };

  std::vector<BondSpring> springs(bonds.size());
  for (std::size_t q = 0; q < bonds.size(); ++q) {
    const Bond& e = graph.bonds[static_cast<std::size_t>(bonds[q])];
    springs[q] = bond_spring(graph, bonds[q], material);
    const std::array<Matrix6, 4> blocks = bond_blocks(springs[q]);
    const int ends[2] = {local[static_cast<std::size_t>(e.a)], local[static_cast<std::size_t>(e.b)]};
    for (int x = 0; x < 2; ++x)
      for (int y = 0; y < 2; ++y)
        if (ends[x] >= 0 && ends[y] >= 0) add_block(ends[y], ends[x], blocks[static_cast<std::size_t>(2 * x + y)]);
  }

  Vector f(n), u(n);
  for (int i = 0; i < nf; ++i)
    for (int k = 0; k < 6; ++k) {
      const std::size_t g = 6 * static_cast<std::size_t>(free_nodes[static_cast<std::size_t>(i)]) + static_cast<std::size_t>(k);
      f[6 * i + k] = loads[g];
      u[6 * i + k] = displacements[g];
    }
  if (n > 0 && f.squaredNorm() > 0.0) {
    report = solve_linear(std::move(stiffness), f, u, settings);
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
    forces[static_cast<std::size_t>(bonds[q])] = bond_forces(e, springs[q], displacements.data() + 6 * static_cast<std::size_t>(e.a),
                                                             displacements.data() + 6 * static_cast<std::size_t>(e.b));
  }
  return report;
}

}  // namespace shatter
