#include "algorithms/stress/rigid_body_spring/cascade_solver.h"

#include "algorithms/stress/rigid_body_spring/decoupled_blocks.h"
#include "algorithms/stress/rigid_body_spring/sparse_product.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shatter {

namespace {

using Vector = Eigen::VectorXd;

/// x(unknowns)
Vector gather(const Vector& x, const std::vector<int>& unknowns) {
  Vector out(static_cast<Eigen::Index>(unknowns.size()));
  for (std::size_t i = 0; i < unknowns.size(); ++i) out[static_cast<Eigen::Index>(i)] = x[unknowns[i]];
  return out;
}

}  // namespace

CascadeSolver::CascadeSolver(const Material& material, const SpringSolverSettings& settings, AnalysisPool& pool)
    : material_(material), settings_(settings), pool_(pool) {}

void CascadeSolver::build(const SupportGraph& graph) {
  stiffness_.emplace(graph, material_);
  // The split is that of the intact K; couplings_negligible() checks it still holds in each round.
  const std::vector<std::uint8_t> all(graph.bonds.size(), 1), none(graph.nodes.size(), 0);
  stiffness_->assemble(all, none);
  const Eigen::SparseMatrix<double>& k = stiffness_->matrix();
  std::vector<int> block_of(static_cast<std::size_t>(k.cols()), -1), position(static_cast<std::size_t>(k.cols()), -1);
  for (std::vector<int>& unknowns : decoupled_blocks(k, settings_.decoupling_tolerance)) {
    for (std::size_t i = 0; i < unknowns.size(); ++i) {
      block_of[static_cast<std::size_t>(unknowns[i])] = static_cast<int>(blocks_.size());
      position[static_cast<std::size_t>(unknowns[i])] = static_cast<int>(i);
    }
    blocks_.emplace_back();
    blocks_.back().unknowns = std::move(unknowns);
  }
  const int* outer = k.outerIndexPtr();
  const int* inner = k.innerIndexPtr();
  // The couplings: entries between blocks (K stores no entry that every bond leaves zero, so a split
  // along such zeros, as between the halves of a planar wall, has none). Each is listed under its
  // column's free node and its row's (unknowns are 6 per free node), by counting.
  const std::size_t free_nodes = static_cast<std::size_t>(k.cols()) / 6;
  node_coupling_start_.assign(free_nodes + 1, 0);
  std::vector<int> ends;  // column node, row node of each coupling
  for (int c = 0; c < k.cols(); ++c)
    for (int at = outer[c]; at < outer[c + 1]; ++at)
      if (block_of[static_cast<std::size_t>(inner[at])] != block_of[static_cast<std::size_t>(c)]) {
        couplings_.push_back(Coupling{at, stiffness_->diagonal_index(inner[at]), stiffness_->diagonal_index(c)});
        ends.push_back(c / 6);
        ends.push_back(inner[at] / 6);
        ++node_coupling_start_[static_cast<std::size_t>(c / 6) + 1];
        ++node_coupling_start_[static_cast<std::size_t>(inner[at] / 6) + 1];
      }
  for (std::size_t v = 0; v < free_nodes; ++v) node_coupling_start_[v + 1] += node_coupling_start_[v];
  node_couplings_.resize(static_cast<std::size_t>(node_coupling_start_.back()));
  std::vector<int> next(node_coupling_start_.begin(), node_coupling_start_.end() - 1);
  for (std::size_t i = 0; i < ends.size(); ++i)
    node_couplings_[static_cast<std::size_t>(next[static_cast<std::size_t>(ends[i])]++)] = static_cast<int>(i / 2);
  // Each block's lower triangle keeps every stored entry of K inside the block (explicit zeros
  // included, so the pattern does not depend on which bonds are intact). Rows stay sorted: the
  // block's unknowns are ascending.
  for (Block& block : blocks_) {
    const int m = static_cast<int>(block.unknowns.size());
    const int id = block_of[static_cast<std::size_t>(block.unknowns.front())];
    std::vector<int> block_outer(static_cast<std::size_t>(m) + 1, 0), rows;
    for (int c = 0; c < m; ++c) {
      const int gc = block.unknowns[static_cast<std::size_t>(c)];
      for (int at = outer[gc]; at < outer[gc + 1]; ++at) {
        const int r = inner[at];
        if (block_of[static_cast<std::size_t>(r)] != id || position[static_cast<std::size_t>(r)] < c) continue;
        rows.push_back(position[static_cast<std::size_t>(r)]);
        block.source.push_back(at);
      }
      block_outer[static_cast<std::size_t>(c) + 1] = static_cast<int>(rows.size());
    }
    block.lower.resize(m, m);
    block.lower.resizeNonZeros(static_cast<Eigen::Index>(rows.size()));
    std::copy(block_outer.begin(), block_outer.end(), block.lower.outerIndexPtr());
    std::copy(rows.begin(), rows.end(), block.lower.innerIndexPtr());
  }
}

CascadeSolver::~CascadeSolver() {
  for (Block& block : blocks_)
    if (block.cholesky && !block.failed)
      pool_.keep(FactorPattern(block.lower, node_groups(block.unknowns)), std::move(*block.cholesky));
}

bool CascadeSolver::couplings_negligible() {
  const double* value = stiffness_->matrix().valuePtr();
  const double t2 = settings_.decoupling_tolerance * settings_.decoupling_tolerance;
  const auto negligible = [&](const Coupling& c) {
    const double v = value[c.value];
    return v == 0.0 || v * v <= t2 * std::abs(value[c.row_diagonal] * value[c.column_diagonal]);
  };
  bool ok = true;
  if (!couplings_known_negligible_) {
    for (const Coupling& c : couplings_) ok = ok && negligible(c);
  } else {
    for (const int v : stiffness_->rebuilt_nodes()) {
      const std::size_t free = static_cast<std::size_t>(stiffness_->first_unknown(v)) / 6;
      for (int at = node_coupling_start_[free]; ok && at < node_coupling_start_[free + 1]; ++at)
        ok = negligible(couplings_[static_cast<std::size_t>(node_couplings_[static_cast<std::size_t>(at)])]);
      if (!ok) break;
    }
  }
  couplings_known_negligible_ = ok;
  return ok;
}

bool CascadeSolver::factorize(Block& block, bool correct) {
  if (block.factorised) return true;
  if (!block.analysed) {
    block.analysed = true;
    block.cholesky = pool_.take(FactorPattern(block.lower, node_groups(block.unknowns)), block.lower);
    block.direct = block.cholesky && block.cholesky->factor_flops() <= settings_.direct_max_flops;
  }
  if (!block.direct) return false;
  const double* value = stiffness_->matrix().valuePtr();
  double* out = block.lower.valuePtr();
  for (std::size_t i = 0; i < block.source.size(); ++i) out[i] = value[block.source[i]];
  const NodeBlockCholesky* node_blocks = block.cholesky->node_blocks();
  if (correct && node_blocks && block.correction.has_base() &&
      block.correction.update(*node_blocks, block.lower, kCorrectionFlopShare * node_blocks->factor_flops())) {
    block.corrected = true;
    block.factorised = true;
    return true;
  }
  block.corrected = false;
  block.factorised = block.cholesky->factorize(block.lower);
  block.failed = block.failed || !block.factorised;
  if (block.factorised)
    block.correction.reset(std::span<const double>(out, block.source.size()));
  else
    block.correction.clear();
  return block.factorised;
}

Eigen::VectorXd CascadeSolver::block_solve(const Block& block, const Eigen::VectorXd& b) const {
  if (block.corrected && block.correction.active()) return block.correction.solve(*block.cholesky->node_blocks(), b);
  return block.cholesky->solve(b);
}

std::optional<SolverReport> CascadeSolver::solve(const SupportGraph& graph, const GraphComponents& components,
                                                 std::span<const std::uint8_t> broken, std::span<const std::uint8_t> solve_now,
                                                 std::span<const double> loads, std::vector<double>& displacements,
                                                 std::vector<BondForces>& forces, bool continues) {
  if (!stiffness_) build(graph);
  for (const Block& block : blocks_)
    if (block.analysed && !block.direct) return std::nullopt;  // a CG block: the per-component path

  // This round's K: the intact bonds of anchored components; the falling clusters' nodes as identity.
  std::vector<std::uint8_t> include(graph.bonds.size(), 0), identity(graph.nodes.size(), 0);
  for (std::size_t b = 0; b < include.size(); ++b)
    include[b] = !broken[b] && components.anchored[static_cast<std::size_t>(
                                   components.component_of[static_cast<std::size_t>(graph.bonds[b].a)])];
  for (std::size_t v = 0; v < identity.size(); ++v)
    identity[v] = !components.anchored[static_cast<std::size_t>(components.component_of[v])];
  stiffness_->assemble(include, identity);
  if (!couplings_negligible()) return std::nullopt;
  const Eigen::SparseMatrix<double>& k = stiffness_->matrix();

  // Loads of the components solved now; the others (and the identity rows) have f = 0, hence u = 0.
  const Eigen::Index n = k.cols();
  Vector f = Vector::Zero(n), u = Vector::Zero(n);
  for (std::size_t c = 0; c < components.nodes.size(); ++c)
    if (solve_now[c])
      for (const int v : components.nodes[c])
        if (const int i = stiffness_->first_unknown(v); i >= 0)
          for (int q = 0; q < 6; ++q) f[i + q] = loads[6 * static_cast<std::size_t>(v) + static_cast<std::size_t>(q)];

  // As solve_linear's block path: loaded blocks solved, then refinement against the whole K, an
  // unloaded block factorised only when its residual is above the round-off of f. A continuing round
  // first tries the blocks' corrections; if the refined residual is not within kMaxCorrectedResidual
  // it refactorises and solves again.
  if (!continues)
    for (Block& block : blocks_) block.correction.clear();
  const double negligible = std::numeric_limits<double>::epsilon() * f.norm();
  Vector r;
  bool corrected = false;
  for (const bool correct : {continues, false}) {
    for (Block& block : blocks_) block.factorised = false, block.corrected = false;
    u.setZero();
    for (Block& block : blocks_) {
      const Vector fb = gather(f, block.unknowns);
      if (fb.squaredNorm() == 0.0) continue;
      if (!factorize(block, correct)) return std::nullopt;
      const Vector x = block_solve(block, fb);
      for (std::size_t i = 0; i < block.unknowns.size(); ++i) u[block.unknowns[i]] = x[static_cast<Eigen::Index>(i)];
    }
    double last = std::numeric_limits<double>::infinity();
    std::optional<Vector> final_residual;  // set by a refinement that ended with it
    for (int step = 0; step < settings_.refinement_steps; ++step) {
      Vector step_r = sparse_residual(k, f, u);
      const double now = step_r.norm();
      if (!refinement_pays(last, now, settings_)) {
        final_residual = std::move(step_r);
        break;
      }
      last = now;
      for (Block& block : blocks_) {
        const Vector rb = gather(step_r, block.unknowns);
        if (rb.norm() <= negligible) continue;
        if (!factorize(block, correct)) return std::nullopt;
        const Vector x = block_solve(block, rb);
        for (std::size_t i = 0; i < block.unknowns.size(); ++i) u[block.unknowns[i]] += x[static_cast<Eigen::Index>(i)];
      }
    }
    if (!u.allFinite()) return std::nullopt;
    r = final_residual ? std::move(*final_residual) : sparse_residual(k, f, u);
    corrected = std::any_of(blocks_.begin(), blocks_.end(), [](const Block& b) { return b.corrected; });
    if (!corrected) {
      ++refactorised_rounds_;
      break;
    }
    if (r.norm() <= kMaxCorrectedResidual * f.norm()) {
      ++corrected_rounds_;
      break;
    }
    for (Block& block : blocks_) block.correction.clear();  // refactorise: the retry must not correct
  }

  // Per component, as if solved alone: residual against its own rows, its displacements, its forces.
  SolverReport report;
  for (std::size_t c = 0; c < components.nodes.size(); ++c) {
    if (!solve_now[c]) continue;
    double r2 = 0.0, f2 = 0.0;
    int free = 0;
    for (const int v : components.nodes[c])
      if (const int i = stiffness_->first_unknown(v); i >= 0) {
        ++free;
        for (int q = 0; q < 6; ++q) r2 += r[i + q] * r[i + q], f2 += f[i + q] * f[i + q];
      }
    report.unknowns = std::max(report.unknowns, 6 * free);
    const bool loaded = free > 0 && f2 > 0.0;
    if (loaded) {
      ++report.solves;
      report.residual = std::max(report.residual, std::sqrt(r2) / std::sqrt(f2));
    }
    for (const int v : components.nodes[c]) {
      const int i = stiffness_->first_unknown(v);
      for (int q = 0; q < 6; ++q)
        displacements[6 * static_cast<std::size_t>(v) + static_cast<std::size_t>(q)] = i >= 0 && loaded ? u[i + q] : 0.0;
    }
    for (const int b : components.bonds[c]) {
      const Bond& e = graph.bonds[static_cast<std::size_t>(b)];
      forces[static_cast<std::size_t>(b)] = bond_forces(e, stiffness_->spring(b), displacements.data() + 6 * static_cast<std::size_t>(e.a),
                                                        displacements.data() + 6 * static_cast<std::size_t>(e.b));
    }
  }
  return report;
}

}  // namespace shatter
