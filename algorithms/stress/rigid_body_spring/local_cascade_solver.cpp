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
/// `ends` (#bonds) and `anchors` (#nodes) are the graph's bond ends and anchored flags in compact arrays
/// (a pass over them reads a twentieth of what one over the graph's bonds reads); `parent` is scratch
/// (#nodes), kept by the caller so that a round allocates nothing for it.
struct NodeComponents {
  std::vector<std::uint8_t> anchored;          // #nodes: 1 when the node's component holds an anchor
  std::vector<std::vector<int>> falling;       // node lists of the unanchored components, by smallest node
  std::size_t free_nodes = 0;                  // nodes of anchored components that are not anchors
};

NodeComponents node_components(std::span<const std::array<int, 2>> ends, std::span<const std::uint8_t> anchors,
                               std::span<const std::uint8_t> broken, std::vector<int>& parent) {
  const std::size_t n = anchors.size();
  parent.resize(n);
  for (std::size_t v = 0; v < n; ++v) parent[v] = static_cast<int>(v);
  const auto find = [&](int v) {
    while (parent[static_cast<std::size_t>(v)] != v) {
      parent[static_cast<std::size_t>(v)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
      v = parent[static_cast<std::size_t>(v)];
    }
    return v;
  };
  for (std::size_t i = 0; i < ends.size(); ++i) {
    if (broken[i]) continue;
    const int ra = find(ends[i][0]), rb = find(ends[i][1]);
    if (ra != rb) parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
  }
  // Every root is its component's smallest node, so in node order a root comes before its members:
  // one pass flattens the forest (parent[v] becomes v's root) and labels the components.
  NodeComponents out;
  out.anchored.assign(n, 0);
  for (std::size_t v = 0; v < n; ++v) {
    const std::size_t r = static_cast<std::size_t>(parent[static_cast<std::size_t>(parent[v])]);
    parent[v] = static_cast<int>(r);
    if (anchors[v]) out.anchored[r] = 1;
  }
  std::vector<int> cluster;
  for (std::size_t v = 0; v < n; ++v) {
    const std::size_t r = static_cast<std::size_t>(parent[v]);
    out.anchored[v] = out.anchored[r];
    if (out.anchored[v]) {
      out.free_nodes += anchors[v] ? 0 : 1;
      continue;
    }
    if (cluster.empty()) cluster.assign(n, -1);
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
                                       const SpringSolverSettings& settings, int hops, bool exact_start)
    : exact_(graph, material, criterion, settings),
      material_(material),
      criterion_(criterion),
      settings_(settings),
      hops_(hops),
      exact_start_(exact_start),
      stiffness_(graph, material) {
  assert(hops >= 1);
  bond_ends_.reserve(graph.bonds.size());
  for (const Bond& b : graph.bonds) bond_ends_.push_back({b.a, b.b});
  anchors_.reserve(graph.nodes.size());
  for (const SupportNode& v : graph.nodes) anchors_.push_back(v.anchored ? 1 : 0);
}

LocalCascadeSolver::~LocalCascadeSolver() = default;

Result<StressResult> LocalCascadeSolver::evaluate(const Loads& loads) {
  if (rest_loads_ == loads) return rest_;
  Result<StressResult> r = exact_.evaluate(loads);
  if (r) {
    rest_ = *r;
    rest_loads_ = loads;
  }
  return r;
}

Result<StressResult> LocalCascadeSolver::reevaluate(const Loads& loads, const StressResult& previous,
                                                    std::span<const int> touched) {
  const SupportGraph& graph = exact_.graph();
  if (previous.displacements.size() == 6 * graph.nodes.size()) return solve_window(loads, previous, touched);
  assert(previous.bonds.size() == graph.bonds.size());
  // A cascade's start: its breaks, windowed from the structure at rest.
  std::vector<int> ends;
  for (std::size_t i = 0; i < previous.bonds.size(); ++i)
    if (previous.bonds[i].broken) ends.insert(ends.end(), bond_ends_[i].begin(), bond_ends_[i].end());
  if (exact_start_ || ends.empty()) return exact_.reevaluate(loads, previous, touched);
  Result<StressResult> rest = evaluate(loads);
  if (!rest) return rest.error();
  // A structure whose rest state is not an answer (not converged) starts exactly, as without the window.
  if (!rest->report.converged) return exact_.reevaluate(loads, previous, touched);
  StressResult start = std::move(*rest);
  for (std::size_t i = 0; i < previous.bonds.size(); ++i)
    if (previous.bonds[i].broken) start.bonds[i].broken = true;
  return solve_window(loads, start, ends);
}

Result<StressResult> LocalCascadeSolver::solve_window(const Loads& loads, const StressResult& previous,
                                                      std::span<const int> touched) {
  const SupportGraph& graph = exact_.graph();
  if (Status s = check_material(material_); !s) return s.error();
  if (Status s = check_loads(loads, graph); !s) return s.error();
  assert(previous.bonds.size() == graph.bonds.size());

  // One pass over the previous bonds reads their broken flags and checks the figures of the intact
  // ones (judge_finite's rule; broken bonds are zeroed below), so that what this round copies from
  // `previous` is checked as it is read.
  std::vector<std::uint8_t>& broken = broken_;
  broken.resize(graph.bonds.size());
  bool finite = true;
  for (std::size_t i = 0; i < broken.size(); ++i) {
    const BondStress& b = previous.bonds[i];
    broken[i] = b.broken ? 1 : 0;
    finite &= b.broken || bond_finite(b);
  }
  NodeComponents components = node_components(bond_ends_, anchors_, broken, parent_);
  // The node loads depend on the loads only: made and checked once for each new `loads`.
  if (f_loads_ != loads) {
    f_loads_.reset();
    f_ = node_loads(graph, loads, material_);
    if (Status s = check_node_loads(f_); !s) return s.error();
    f_loads_ = loads;
  }

  const CascadeWindow window = cascade_window(graph, broken, components.anchored, touched, hops_);
  // A window over half the free nodes or more costs about what the exact round costs, whose cascade
  // solver keeps its analyses and factors from round to round: take the exact round.
  if (!window.nodes.empty() && 2 * window.nodes.size() >= components.free_nodes)
    return exact_.reevaluate(loads, previous, touched);

  StressResult out;
  out.bonds = previous.bonds;
  out.displacements = previous.displacements;
  finite &= values_finite(out.displacements);
  // Broken bonds carry nothing; a falling cluster is never solved, as in the exact model.
  for (std::size_t i = 0; i < broken.size(); ++i)
    if (broken[i]) out.bonds[i] = BondStress{.broken = true};
  for (const std::vector<int>& cluster : components.falling)
    for (const int v : cluster) {
      std::fill_n(out.displacements.begin() + 6 * static_cast<std::ptrdiff_t>(v), 6, 0.0);
      for (const int b : graph.node_bonds[static_cast<std::size_t>(v)])
        if (!broken[static_cast<std::size_t>(b)]) out.bonds[static_cast<std::size_t>(b)] = BondStress{};
    }
  out.falling_clusters = std::move(components.falling);

  if (!window.nodes.empty()) {
    // The window is solved as a component (solve_component) whose bonds to the nodes outside it hold
    // those nodes fixed, as it holds anchored ones; their displacements move to the right-hand side.
    // The corrections go into the kept node loads and come out again after the solve.
    std::vector<double> window_loads(6 * window.nodes.size());
    for (std::size_t k = 0; k < window.nodes.size(); ++k)
      std::copy_n(f_.begin() + 6 * static_cast<std::ptrdiff_t>(window.nodes[k]), 6, window_loads.begin() + 6 * static_cast<std::ptrdiff_t>(k));
    std::vector<int>& bonds = window_bonds_;
    bonds.clear();
    std::vector<std::array<int, 2>>& boundary = boundary_;  // (window node, bond to a node outside)
    boundary.clear();
    for (const int v : window.nodes) {
      const int i = window.index[static_cast<std::size_t>(v)];
      for (const int b : graph.node_bonds[static_cast<std::size_t>(v)]) {
        if (broken[static_cast<std::size_t>(b)]) continue;
        const int other = bond_ends_[static_cast<std::size_t>(b)][0] == v ? bond_ends_[static_cast<std::size_t>(b)][1]
                                                                          : bond_ends_[static_cast<std::size_t>(b)][0];
        const int j = window.index[static_cast<std::size_t>(other)];
        if (j >= 0) {
          if (j > i) bonds.push_back(b);  // a bond inside: once
          continue;
        }
        bonds.push_back(b);
        boundary.push_back({v, b});
      }
    }
    stiffness_.prepare(bonds);
    for (const auto [v, b] : boundary) {
      // blocks[2 x + y] couples node y's equations to node x's unknowns (x, y: 0 = a, 1 = b).
      const bool is_a = bond_ends_[static_cast<std::size_t>(b)][0] == v;
      const int other = bond_ends_[static_cast<std::size_t>(b)][is_a ? 1 : 0];
      const Eigen::Map<const Eigen::Matrix<double, 6, 1>> u_other(out.displacements.data() + 6 * other);
      Eigen::Map<Eigen::Matrix<double, 6, 1>>(f_.data() + 6 * v) -= stiffness_.at(b).blocks[is_a ? 2 : 1] * u_other;
    }
    if (forces_.size() != graph.bonds.size()) forces_.resize(graph.bonds.size());
    out.report = solve_component(graph, window.nodes, bonds, f_, material_, settings_, memory_,
                                 out.displacements, forces_, &stiffness_);
    for (std::size_t k = 0; k < window.nodes.size(); ++k)
      std::copy_n(window_loads.begin() + 6 * static_cast<std::ptrdiff_t>(k), 6, f_.begin() + 6 * static_cast<std::ptrdiff_t>(window.nodes[k]));
    for (const int b : bonds) {
      BondStress& stress = out.bonds[static_cast<std::size_t>(b)];
      stress = bond_stress(graph.bonds[static_cast<std::size_t>(b)], forces_[static_cast<std::size_t>(b)], material_, criterion_);
      finite &= bond_finite(stress);
    }
    for (const int v : window.nodes)
      finite &= values_finite(std::span<const double>(out.displacements).subspan(6 * static_cast<std::size_t>(v), 6));
  }
  judge_convergence(out.report, solve_tolerance(settings_));
  if (!finite) {
    out.report.finite = false;
    out.report.converged = false;
  }
  return out;
}

}  // namespace shatter
