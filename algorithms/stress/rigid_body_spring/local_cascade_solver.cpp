#include "algorithms/stress/rigid_body_spring/local_cascade_solver.h"

#include "algorithms/stress/rigid_body_spring/bond_spring.h"
#include "algorithms/stress/rigid_body_spring/spring_system.h"

#include <algorithm>
#include <array>
#include <cassert>

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
  std::vector<double> f = node_loads(graph, loads, material_);
  if (Status s = check_node_loads(f); !s) return s.error();

  const CascadeWindow window = cascade_window(graph, broken, components.anchored, touched, hops_);
  // A window over half the free nodes or more costs about what the exact round costs, whose cascade
  // solver keeps its analyses and factors from round to round: take the exact round.
  if (!window.nodes.empty() && 2 * window.nodes.size() >= free_nodes) return exact_.reevaluate(loads, previous, touched);

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

  if (!window.nodes.empty()) {
    // The window is solved as a component (solve_component) whose bonds to the nodes outside it hold
    // those nodes fixed, as it holds anchored ones; their displacements move to the right-hand side.
    std::vector<int> bonds;
    std::array<Matrix6, 4> blocks;
    for (const int v : window.nodes) {
      const int i = window.index[static_cast<std::size_t>(v)];
      for (const int b : graph.node_bonds[static_cast<std::size_t>(v)]) {
        if (broken[static_cast<std::size_t>(b)]) continue;
        const Bond& bond = graph.bonds[static_cast<std::size_t>(b)];
        const bool is_a = bond.a == v;
        const int other = is_a ? bond.b : bond.a;
        const int j = window.index[static_cast<std::size_t>(other)];
        if (j >= 0) {
          if (j > i) bonds.push_back(b);  // a bond inside: once
          continue;
        }
        bonds.push_back(b);
        // blocks[2 x + y] couples node y's equations to node x's unknowns (x, y: 0 = a, 1 = b).
        bond_blocks(bond_spring(graph, b, material_), blocks);
        const Eigen::Map<const Eigen::Matrix<double, 6, 1>> u_other(out.displacements.data() + 6 * other);
        Eigen::Map<Eigen::Matrix<double, 6, 1>>(f.data() + 6 * v) -= blocks[is_a ? 2 : 1] * u_other;
      }
    }
    if (forces_.size() != graph.bonds.size()) forces_.resize(graph.bonds.size());
    out.report = solve_component(graph, window.nodes, bonds, f, material_, settings_, memory_,
                                 out.displacements, forces_);
    for (const int b : bonds)
      out.bonds[static_cast<std::size_t>(b)] =
          bond_stress(graph.bonds[static_cast<std::size_t>(b)], forces_[static_cast<std::size_t>(b)], material_, criterion_);
  }
  judge_convergence(out.report, solve_tolerance(settings_));
  judge_finite(out);
  return out;
}

}  // namespace shatter
