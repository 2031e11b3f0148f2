#include "algorithms/stress/rigid_body_spring/local_cascade_solver.h"

#include "algorithms/stress/rigid_body_spring/bond_spring.h"
#include "algorithms/stress/rigid_body_spring/spring_system.h"

#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace shatter {

namespace {

/// Which nodes belong to an anchored component, and the falling clusters (as graph_components and
/// falling_clusters give them), by union-find without the per-component lists a round does not need.
struct NodeComponents {
  std::vector<std::uint8_t> anchored;          // #nodes: 1 when the node's component holds an anchor
  std::vector<std::vector<int>> falling;       // node lists of the unanchored components, by smallest node
};

NodeComponents node_components(const SupportGraph& graph, std::span<const std::uint8_t> broken) {
  const std::size_t n = graph.nodes.size();
  std::vector<int> parent(n);
  for (std::size_t v = 0; v < n; ++v) parent[v] = static_cast<int>(v);
  const auto find = [&](int v) {
    while (parent[static_cast<std::size_t>(v)] != v) {
      parent[static_cast<std::size_t>(v)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
      v = parent[static_cast<std::size_t>(v)];
    }
    return v;
  };
  for (std::size_t i = 0; i < graph.bonds.size(); ++i) {
    if (broken[i]) continue;
    const int ra = find(graph.bonds[i].a), rb = find(graph.bonds[i].b);
    if (ra != rb) parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
  }
  NodeComponents out;
  out.anchored.assign(n, 0);
  std::vector<int> root(n);
  for (std::size_t v = 0; v < n; ++v) {
    root[v] = find(static_cast<int>(v));
    if (graph.nodes[v].anchored) out.anchored[static_cast<std::size_t>(root[v])] = 1;
  }
  std::vector<int> cluster(n, -1);
  for (std::size_t v = 0; v < n; ++v) {
    const std::size_t r = static_cast<std::size_t>(root[v]);
    out.anchored[v] = out.anchored[r];
    if (out.anchored[v]) continue;
    if (cluster[r] < 0) {
      cluster[r] = static_cast<int>(out.falling.size());
      out.falling.emplace_back();
    }
    out.falling[static_cast<std::size_t>(cluster[r])].push_back(static_cast<int>(v));
  }
  return out;
}

}  // namespace

CascadeWindow cascade_window(const SupportGraph& graph, std::span<const std::uint8_t> broken,
                             std::span<const std::uint8_t> anchored_component, std::span<const int> seeds, int hops) {
  CascadeWindow w;
  w.index.assign(graph.nodes.size(), -1);
  const auto is_free = [&](int v) {
    return anchored_component[static_cast<std::size_t>(v)] != 0 && !graph.nodes[static_cast<std::size_t>(v)].anchored;
  };
  for (const int v : seeds) {
    if (!is_free(v) || w.index[static_cast<std::size_t>(v)] >= 0) continue;
    w.index[static_cast<std::size_t>(v)] = static_cast<int>(w.nodes.size());
    w.nodes.push_back(v);
  }
  std::size_t level_begin = 0;
  for (int hop = 0; hop < hops; ++hop) {
    const std::size_t level_end = w.nodes.size();
    if (level_begin == level_end) break;
    for (std::size_t i = level_begin; i < level_end; ++i) {
      const int v = w.nodes[i];
      for (const int b : graph.node_bonds[static_cast<std::size_t>(v)]) {
        if (broken[static_cast<std::size_t>(b)]) continue;
        const Bond& bond = graph.bonds[static_cast<std::size_t>(b)];
        const int other = bond.a == v ? bond.b : bond.a;
        if (!is_free(other) || w.index[static_cast<std::size_t>(other)] >= 0) continue;
        w.index[static_cast<std::size_t>(other)] = static_cast<int>(w.nodes.size());
        w.nodes.push_back(other);
      }
    }
    level_begin = level_end;
  }
  return w;
}

LocalCascadeSolver::LocalCascadeSolver(const SupportGraph& graph, const Material& material, Criterion criterion,
                                       const SpringSolverSettings& settings, int hops)
    : exact_(graph, material, criterion, settings),
      material_(material),
      criterion_(criterion),
      settings_(settings),
      hops_(hops) {
  assert(hops >= 1);
}

LocalCascadeSolver::~LocalCascadeSolver() = default;

const LocalCascadeSolver::BondBlocks& LocalCascadeSolver::bond_blocks_of(int bond) {
  const SupportGraph& graph = exact_.graph();
  if (bond_blocks_.empty()) {
    bond_blocks_.resize(graph.bonds.size());
    blocks_made_.assign(graph.bonds.size(), 0);
  }
  BondBlocks& bb = bond_blocks_[static_cast<std::size_t>(bond)];
  if (!blocks_made_[static_cast<std::size_t>(bond)]) {
    bb.spring = bond_spring(graph, bond, material_);
    bond_blocks(bb.spring, bb.blocks);
    blocks_made_[static_cast<std::size_t>(bond)] = 1;
  }
  return bb;
}

Result<StressResult> LocalCascadeSolver::evaluate(const Loads& loads) { return exact_.evaluate(loads); }

Result<StressResult> LocalCascadeSolver::reevaluate(const Loads& loads, const StressResult& previous,
                                                    std::span<const int> touched) {
  const SupportGraph& graph = exact_.graph();
  const std::size_t n = graph.nodes.size();
  if (previous.displacements.size() != 6 * n) return exact_.reevaluate(loads, previous, touched);
  if (Status s = check_material(material_); !s) return s.error();
  if (Status s = check_loads(loads, graph); !s) return s.error();
  assert(previous.bonds.size() == graph.bonds.size());

  std::vector<std::uint8_t> broken(graph.bonds.size(), 0);
  for (std::size_t i = 0; i < broken.size(); ++i) broken[i] = previous.bonds[i].broken ? 1 : 0;
  const NodeComponents components = node_components(graph, broken);
  std::size_t free_nodes = 0;
  for (std::size_t v = 0; v < n; ++v) free_nodes += components.anchored[v] && !graph.nodes[v].anchored ? 1 : 0;
  const std::vector<double> f = node_loads(graph, loads, material_);
  if (Status s = check_node_loads(f); !s) return s.error();

  const CascadeWindow window = cascade_window(graph, broken, components.anchored, touched, hops_);
  // A window over half the free nodes or more costs about what the exact round costs, whose cascade
  // solver keeps its analyses and factors from round to round: take the exact round.
  if (!window.nodes.empty() && 2 * window.nodes.size() >= free_nodes) return exact_.reevaluate(loads, previous, touched);
  WindowSolve solved;
  if (!window.nodes.empty()) solved = solve_window(window, previous, broken, f);
  else judge_convergence(solved.report, solve_tolerance(settings_));  // nothing to solve: converged, as judged

  StressResult out;
  out.bonds = previous.bonds;
  out.displacements = previous.displacements;
  out.falling_clusters = components.falling;
  // Broken bonds carry nothing; a falling cluster is never solved, as in the exact model.
  for (std::size_t i = 0; i < broken.size(); ++i) {
    if (broken[i]) {
      out.bonds[i] = BondStress{.broken = true};
    } else if (!components.anchored[static_cast<std::size_t>(graph.bonds[i].a)]) {
      out.bonds[i] = BondStress{};
    }
  }
  for (const std::vector<int>& cluster : components.falling)
    for (const int v : cluster) std::fill_n(out.displacements.begin() + 6 * static_cast<std::ptrdiff_t>(v), 6, 0.0);
  out.report = solved.report;
  for (std::size_t i = 0; i < window.nodes.size(); ++i)
    std::copy_n(solved.displacements.data() + 6 * static_cast<std::ptrdiff_t>(i), 6,
                out.displacements.begin() + 6 * static_cast<std::ptrdiff_t>(window.nodes[i]));
  for (std::size_t j = 0; j < solved.bonds.size(); ++j) out.bonds[static_cast<std::size_t>(solved.bonds[j])] = solved.stresses[j];
  judge_finite(out);
  return out;
}

LocalCascadeSolver::WindowSolve LocalCascadeSolver::solve_window(const CascadeWindow& window,
                                                                 const StressResult& previous,
                                                                 std::span<const std::uint8_t> broken,
                                                                 std::span<const double> f) {
  const SupportGraph& graph = exact_.graph();
  const int m = static_cast<int>(window.nodes.size());
  WindowSolve out;
  // The window's system: its nodes' equations, the boundary's displacements moved to the right side.
  Eigen::VectorXd rhs(6 * m);
  for (int i = 0; i < m; ++i)
    for (int c = 0; c < 6; ++c) rhs[6 * i + c] = f[6 * static_cast<std::size_t>(window.nodes[static_cast<std::size_t>(i)]) + static_cast<std::size_t>(c)];
  // K's columns node by node: each window node's diagonal block, then its couplings to the window
  // nodes it shares a bond with (K(j, i): node j's equations, node i's unknowns), sorted by j.
  struct Coupling {
    int node;               // window index of the row node
    const Matrix6* block;   // K(node, column node)
  };
  std::vector<Matrix6> diagonal(static_cast<std::size_t>(m), Matrix6::Zero());
  std::vector<Coupling> couplings;
  std::vector<int> coupling_start(static_cast<std::size_t>(m) + 1, 0);
  for (int i = 0; i < m; ++i) {
    const int v = window.nodes[static_cast<std::size_t>(i)];
    coupling_start[static_cast<std::size_t>(i)] = static_cast<int>(couplings.size());
    for (const int b : graph.node_bonds[static_cast<std::size_t>(v)]) {
      if (broken[static_cast<std::size_t>(b)]) continue;
      const Bond& bond = graph.bonds[static_cast<std::size_t>(b)];
      const BondBlocks& bb = bond_blocks_of(b);
      // blocks[2 x + y] couples node y's equations to node x's unknowns (x, y: 0 = a, 1 = b).
      const bool is_a = bond.a == v;
      const int other = is_a ? bond.b : bond.a;
      const int j = window.index[static_cast<std::size_t>(other)];
      diagonal[static_cast<std::size_t>(i)] += bb.blocks[is_a ? 0 : 3];
      if (j >= 0) {
        couplings.push_back({j, &bb.blocks[is_a ? 1 : 2]});
        if (j > i) out.bonds.push_back(b);  // a bond inside: once
      } else {
        const Eigen::Map<const Eigen::Matrix<double, 6, 1>> u_other(previous.displacements.data() + 6 * other);
        rhs.segment<6>(6 * i) -= bb.blocks[is_a ? 2 : 1] * u_other;
        out.bonds.push_back(b);
      }
    }
    std::sort(couplings.begin() + coupling_start[static_cast<std::size_t>(i)], couplings.end(),
              [](const Coupling& x, const Coupling& y) { return x.node < y.node; });
  }
  coupling_start[static_cast<std::size_t>(m)] = static_cast<int>(couplings.size());

  // Both triangles, every 6 x 6 block whole (explicit zeros kept), two bonds between one pair summed.
  std::vector<std::vector<std::pair<int, Matrix6>>> columns(static_cast<std::size_t>(m));
  std::size_t nnz = 0;
  for (int i = 0; i < m; ++i) {
    std::vector<std::pair<int, Matrix6>>& column = columns[static_cast<std::size_t>(i)];
    bool diagonal_placed = false;
    for (int c = coupling_start[static_cast<std::size_t>(i)]; c < coupling_start[static_cast<std::size_t>(i) + 1]; ++c) {
      const Coupling& cp = couplings[static_cast<std::size_t>(c)];
      if (!diagonal_placed && cp.node > i) {
        column.emplace_back(i, diagonal[static_cast<std::size_t>(i)]);
        diagonal_placed = true;
      }
      if (!column.empty() && column.back().first == cp.node) column.back().second += *cp.block;
      else column.emplace_back(cp.node, *cp.block);
    }
    if (!diagonal_placed) column.emplace_back(i, diagonal[static_cast<std::size_t>(i)]);
    nnz += 36 * column.size();
  }
  Eigen::SparseMatrix<double> k(6 * m, 6 * m);
  k.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = k.outerIndexPtr();
  int* inner = k.innerIndexPtr();
  double* values = k.valuePtr();
  int at = 0;
  for (int i = 0; i < m; ++i)
    for (int c = 0; c < 6; ++c) {
      outer[6 * i + c] = at;
      for (const auto& [row_node, block] : columns[static_cast<std::size_t>(i)])
        for (int r = 0; r < 6; ++r) {
          inner[at] = 6 * row_node + r;
          values[at] = block(r, c);
          ++at;
        }
    }
  outer[6 * m] = at;

  // The window's system is a component's system with a fixed boundary: the same solve (split into
  // decoupled blocks, node-block Cholesky, refinement), its residual judged by the same rule.
  Eigen::VectorXd u(6 * m);
  for (int i = 0; i < m; ++i)
    for (int c = 0; c < 6; ++c)
      u[6 * i + c] = previous.displacements[6 * static_cast<std::size_t>(window.nodes[static_cast<std::size_t>(i)]) + static_cast<std::size_t>(c)];
  out.report = solve_linear(std::move(k), rhs, u, settings_, memory_);
  out.report.solves = 1;
  out.report.unknowns = 6 * m;
  judge_convergence(out.report, solve_tolerance(settings_));
  out.displacements.assign(u.data(), u.data() + u.size());

  // The displacement of a bond's end: the window's new one, or the boundary's previous one.
  const auto displacement = [&](int node) {
    const int i = window.index[static_cast<std::size_t>(node)];
    return i >= 0 ? out.displacements.data() + 6 * static_cast<std::ptrdiff_t>(i)
                  : previous.displacements.data() + 6 * static_cast<std::ptrdiff_t>(node);
  };
  out.stresses.reserve(out.bonds.size());
  for (const int b : out.bonds) {
    const Bond& bond = graph.bonds[static_cast<std::size_t>(b)];
    const BondForces forces = bond_forces(bond, bond_blocks_of(b).spring, displacement(bond.a), displacement(bond.b));
    out.stresses.push_back(bond_stress(bond, forces, material_, criterion_));
  }
  return out;
}

}  // namespace shatter
