#pragma once
/// The stress model interface: loads in, per-bond forces, stresses and utilization out, plus the
/// clusters that have lost every path to an anchor.
///
/// Design note: a model is stateless settings; the work worth keeping belongs to a StressSolver, made
/// by the model for one structure (one support graph and material) and owned by its caller, as a
/// stress solver is kept per structure in an engine: the pipeline keeps one per standing structure for
/// a whole run, across every event, and a one-off evaluation makes its own. The solver keeps what
/// depends only on the structure (for the rigid-body-spring models: the stiffness pattern, the block
/// split, orderings, symbolic and numeric factors, the systems solved before); two solvers never
/// share any of it. The state of one cascade (which bonds are broken, the last displacements for a
/// warm start) lives in the StressResult, which `reevaluate` takes back, so "only the affected
/// component is re-solved" is a property the caller can check: components with no touched node are
/// copied from the previous result bit for bit.

#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/result.h"
#include "algorithms/core/material.h"

#include <bit>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace shatter {

/// A force applied to one fragment at a point.
struct PointLoad {
  int node = 0;                   ///< fragment index
  Vec3 point = Vec3::Zero();      ///< point of application, m
  Vec3 force = Vec3::Zero();      ///< N
  bool operator==(const PointLoad&) const = default;
};

/// What the structure carries.
struct Loads {
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);   ///< m/s^2, acts on every fragment's mass at its centroid
  std::vector<PointLoad> point_loads;     ///< extra forces, N
  bool operator==(const Loads&) const = default;
};

/// Forces, stresses and verdict of one bond. Magnitudes are >= 0 unless said otherwise.
struct BondStress {
  double normal_force = 0.0;      ///< N, signed: + tension (b pulled away from a), - compression
  double shear_force = 0.0;       ///< N, in-plane force magnitude
  double bending_moment = 0.0;    ///< N m, magnitude of the in-plane moment
  double torsion = 0.0;           ///< N m, magnitude of the moment about the normal
  double sigma = 0.0;             ///< Pa, peak normal stress magnitude (the governing extreme fibre)
  bool tensile = false;           ///< the governing peak normal stress is tension
  double tau = 0.0;               ///< Pa, peak shear stress
  double utilization = 0.0;       ///< dimensionless, the bond fails when > 1
  bool broken = false;            ///< removed (by propagation, or given broken)
};

/// How the linear solves went (summed over every component solved).
struct SolverReport {
  int solves = 0;                 ///< number of linear systems solved
  int iterations = 0;             ///< iterative-solver iterations, summed (0 for direct solves)
  bool converged = true;          ///< every solve reached its tolerance (residual <= tolerance, finite)
  double residual = 0.0;          ///< largest relative residual |K u - f| / |f|
  double tolerance = 0.0;         ///< largest relative residual a solve may leave and still be converged
  bool finite = true;             ///< every displacement and bond figure came out finite (else not converged)
  int unknowns = 0;               ///< largest system size solved, #DOF
};

/// Marks `report` not converged unless its residual is finite and at most `tolerance` (which it
/// records): the one rule by which every solve of the stress models reports convergence.
void judge_convergence(SolverReport& report, double tolerance);

/// Adds the solves of `r` to `total`: counts summed, the largest residual, tolerance and size, and
/// converged only when both are.
void add_solver_report(SolverReport& total, const SolverReport& r);

/// "the solve did not converge (relative residual R > tolerance T)" for a report that did not
/// converge (or "... gave non-finite forces or displacements"); empty when it did.
std::string convergence_failure(const SolverReport& report);

/// The outcome of one evaluation.
struct StressResult {
  std::vector<BondStress> bonds;                  ///< #bonds, same order as SupportGraph::bonds
  std::vector<std::vector<int>> falling_clusters; ///< fragment indices of each component with no anchor
  std::vector<double> displacements;              ///< 6 #nodes: translation (m) and rotation (rad) per node
  SolverReport report;                            ///< solver statistics
};

/// The stress solve of one structure: a support graph and a material, fixed for the solver's life.
/// Made by StressModel::make_solver and owned by the caller; the graph must outlive it unchanged.
/// Not thread-safe: one solve at a time. Every result is bit for bit what a new solver would give.
class StressSolver {
 public:
  virtual ~StressSolver() = default;
  /// The structure solved.
  [[nodiscard]] virtual const SupportGraph& graph() const = 0;
  /// Evaluates the intact graph. Errors for a bad material or bad loads.
  [[nodiscard]] virtual Result<StressResult> evaluate(const Loads& loads) = 0;
  /// Re-evaluates after bonds were flagged broken in `previous` (#bonds of graph()): components holding
  /// any node of `touched` are solved again (warm-started from `previous.displacements`, when it holds
  /// them), the others are copied. A `previous` without displacements (a fresh start) is solved as a
  /// first evaluation is; one that holds them continues a cascade, reusing the work of its rounds.
  [[nodiscard]] virtual Result<StressResult> reevaluate(const Loads& loads, const StressResult& previous,
                                                        std::span<const int> touched) = 0;
};

/// A stress model. Implementations are stateless settings and thread-compatible.
class StressModel {
 public:
  virtual ~StressModel() = default;
  /// Registered name, e.g. "von-mises".
  [[nodiscard]] virtual std::string_view name() const = 0;
  /// True when the model breaks bonds only through the static solve of anchored components: with zero
  /// loads nothing breaks, and components without an anchor are never evaluated. The frame pipeline
  /// then skips the solve of a scene with no gravity or no anchors (result-neutral by this contract).
  [[nodiscard]] virtual bool driven_by_loads() const { return true; }
  /// A solver for the structure `graph` (which must outlive it unchanged) made of `material`. A bad
  /// material is reported by the solver's evaluations.
  [[nodiscard]] virtual std::unique_ptr<StressSolver> make_solver(const SupportGraph& graph,
                                                                  const Material& material) const = 0;
  /// The model whose cascade is the exact reference for this one's (`shatterbench accuracy --family
  /// cascade`): the same criterion with every round an exact solve. Null (the default) when the model
  /// states none; the accuracy command then reports no cascade error for it.
  [[nodiscard]] virtual std::unique_ptr<StressModel> exact_cascade_reference() const { return nullptr; }
  /// Evaluates the intact `graph` once, with a solver of its own that ends with the call.
  [[nodiscard]] Result<StressResult> evaluate(const SupportGraph& graph, const Loads& loads,
                                              const Material& material) const {
    return make_solver(graph, material)->evaluate(loads);
  }
};


/// Error unless gravity and every point load are finite and refer to existing nodes.
Status check_loads(const Loads& loads, const SupportGraph& graph);

/// Error unless every force a model computed from the loads (6 per node: force, N, and moment, N m) is
/// finite: finite inputs can still overflow (gravity times a huge mass).
Status check_node_loads(std::span<const double> node_loads);

/// Whether every displacement and bond figure of `result` is finite; marks its report not converged
/// (and not finite) when one is not, so that no NaN or Inf is ever reported as a valid answer.
bool judge_finite(StressResult& result);

/// 1 when `x` is infinite or NaN (its exponent bits all set), else 0. An integer test, unlike a chain of
/// std::isfinite, lets a loop over many values vectorise; inline for the loops over every bond.
inline unsigned nonfinite_bit(double x) {
  return (std::bit_cast<std::uint64_t>(x) & 0x7ff0000000000000ULL) == 0x7ff0000000000000ULL ? 1u : 0u;
}

/// Whether every figure of one bond is finite (judge_finite's test for a bond).
inline bool bond_finite(const BondStress& b) {
  return (nonfinite_bit(b.normal_force) | nonfinite_bit(b.shear_force) | nonfinite_bit(b.bending_moment) |
          nonfinite_bit(b.torsion) | nonfinite_bit(b.sigma) | nonfinite_bit(b.tau) | nonfinite_bit(b.utilization)) == 0;
}

/// Whether every value of `values` is finite (judge_finite's test for the displacements).
bool values_finite(std::span<const double> values);

}  // namespace shatter
