#pragma once
/// The static solve of every anchored component of one support graph at once, keeping across the
/// rounds of a cascade all the work that depends only on the intact graph.
///
/// Design note: breaking bonds only removes values from K, so one pattern (the intact graph's, with
/// identity rows for the nodes of falling clusters, graph_stiffness.h) serves every round. The split
/// into decoupled blocks (decoupled_blocks.h), each block's lower-triangle pattern with its gather map
/// from K, and each block's AMD ordering and symbolic analysis (sparse_cholesky.h) are therefore done once; a round
/// costs an assembly by scatter, a gather per block and a numeric factorisation. It is kept for the
/// life of its structure's solver (StrengthCriterionSolver), so every cascade on the structure (every
/// event of a run) starts with all of it; what it reuses gives bit for bit what a new one would (the
/// assembly and the node-block refactorisation recompute exactly what changed). The anchored
/// components share the system but not a single entry, so each one's solution is its own solve's,
/// and the residual is reported per component, as for a solve of the component alone. The path steps
/// aside (the caller solves per component) when it does not apply: a block above the flop limit of
/// the direct solve (CG territory), a factorisation that fails, or a coupling dropped between blocks
/// that has grown above the decoupling tolerance once bonds broke.
///
/// A round that continues the rounds before it (its input is this solver's last output) does not
/// refactorise a block whose changes since its last factorisation cost at most kCorrectionFlopShare
/// of a factorisation to correct: it solves through that factor with a capacitance correction
/// (capacitance_correction.h), refined against the whole K like every direct solve, and refactorises
/// after all when the refined residual is above kMaxCorrectedResidual. Any other round refactorises
/// (bit for bit a factorisation from scratch), so what a round gives depends only on the rounds since
/// the one that broke the chain, never on what the solver solved before (docs/stress.md, section 3a).

#include "algorithms/bonds/graph_components.h"
#include "algorithms/stress/rigid_body_spring/analysis_pool.h"
#include "algorithms/stress/rigid_body_spring/capacitance_correction.h"
#include "algorithms/stress/rigid_body_spring/graph_stiffness.h"
#include "algorithms/stress/rigid_body_spring/linear_solve.h"
#include "algorithms/stress/rigid_body_spring/sparse_cholesky.h"
#include "algorithms/stress/stress_model.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace shatter {

/// A continuing round corrects a block instead of refactorising it while the correction's update is
/// estimated at most this share of a factorisation's flops (a round's partial refactorisation costs
/// about half of one on the walls, docs/stress.md section 3a).
inline constexpr double kCorrectionFlopShare = 0.3;
/// The largest relative residual |f - K u| / |f| a corrected round may end with; above it the round
/// refactorises and solves again.
inline constexpr double kMaxCorrectedResidual = 1e-11;

class CascadeSolver final {
 public:
  /// A solver for one graph (the one every `solve` passes) made of `material`, taking its analyses
  /// from `pool` (which must outlive it); the intact pattern, springs and block split are built by the
  /// first solve (a cascade's first round goes per component and may be its only one).
  CascadeSolver(const Material& material, const SpringSolverSettings& settings, AnalysisPool& pool);
  /// Returns the blocks' analysed factors to the pool.
  ~CascadeSolver();
  CascadeSolver(const CascadeSolver&) = delete;
  CascadeSolver& operator=(const CascadeSolver&) = delete;

  /// Solves the anchored components with `solve_now[c] != 0` (#components of `components`, computed with
  /// `broken`, #bonds) under `loads` (6 #nodes): their nodes' `displacements` (6 #nodes) and their
  /// bonds' `forces` (#bonds) are overwritten, nothing else is. Returns the report summed over those
  /// components as per-component solves would, or nothing when this path does not apply (nothing
  /// written then). `continues`: the state solved is this solver's last output with more bonds
  /// broken, so the factors of the rounds before may be corrected rather than refactorised.
  std::optional<SolverReport> solve(const SupportGraph& graph, const GraphComponents& components,
                                    std::span<const std::uint8_t> broken, std::span<const std::uint8_t> solve_now,
                                    std::span<const double> loads, std::vector<double>& displacements,
                                    std::vector<BondForces>& forces, bool continues = false);
  /// Rounds solved through a capacitance correction, and rounds refactorised (tests, benchmarks).
  [[nodiscard]] int corrected_rounds() const { return corrected_rounds_; }
  [[nodiscard]] int refactorised_rounds() const { return refactorised_rounds_; }

 private:
  /// One decoupled block: its unknowns, the lower triangle of K(block, block) in a fixed pattern, and
  /// its factor (analysed once, factorised in every solve that needs it).
  struct Block {
    std::vector<int> unknowns;             // ascending
    Eigen::SparseMatrix<double> lower;     // fixed pattern, values gathered from K
    std::vector<int> source;               // #entries of lower: index in K's value array
    std::optional<SparseCholesky> cholesky;  // from the analysis pool (analysis_pool.h), then kept
    bool failed = false;                   // a factorisation failed: the factor is not pooled again
    bool analysed = false;                 // ordering and symbolic factor done
    bool direct = false;                   // analysed and within direct_max_flops
    bool factorised = false;               // numeric factor of the current K (or its correction)
    CapacitanceCorrection correction;      // K against the values last factorised
    bool corrected = false;                // this round solves through the correction
  };
  /// An entry of K between two blocks, dropped from both: value index and its diagonal indices.
  struct Coupling {
    int value, row_diagonal, column_diagonal;
  };

  void build(const SupportGraph& graph);
  /// True when every coupling is still below the decoupling tolerance. The first check, and the one
  /// after a failed check, goes over them all; the others only over the couplings in the columns or
  /// rows of the nodes the last assembly rebuilt (the rest have not changed since they passed).
  [[nodiscard]] bool couplings_negligible();
  /// Makes `block` ready to solve with this round's K: corrected when `correct` and the correction
  /// applies, else factorised. False when it cannot be factorised directly.
  bool factorize(Block& block, bool correct);
  /// x = K(block, block)^-1 b with the block's factor or correction.
  [[nodiscard]] Eigen::VectorXd block_solve(const Block& block, const Eigen::VectorXd& b) const;

  Material material_;
  SpringSolverSettings settings_;
  AnalysisPool& pool_;
  std::optional<GraphStiffness> stiffness_;  // built by the first solve
  std::vector<Block> blocks_;
  std::vector<Coupling> couplings_;
  std::vector<int> node_coupling_start_, node_couplings_;  // per free node: couplings in its columns or rows
  bool couplings_known_negligible_ = false;                // every coupling passed the last check
  int corrected_rounds_ = 0, refactorised_rounds_ = 0;
};

}  // namespace shatter
