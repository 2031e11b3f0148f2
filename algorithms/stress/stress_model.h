#pragma once
/// The stress model interface: loads in, per-bond forces, stresses and utilization out, plus the
/// clusters that have lost every path to an anchor.
///
/// Design note: a model is stateless; the state of a cascade (which bonds are broken, the last
/// displacements for a warm start, and whatever solver work the model reuses between rounds, e.g. a
/// matrix ordering) lives in the StressResult, which `reevaluate` takes back. That keeps
/// one model object usable from several pipelines and makes "only the affected component is re-solved"
/// a property the caller can check: components with no touched node are copied from the previous
/// result bit for bit.

#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/result.h"
#include "algorithms/core/material.h"

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
};

/// What the structure carries.
struct Loads {
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);   ///< m/s^2, acts on every fragment's mass at its centroid
  std::vector<PointLoad> point_loads;     ///< extra forces, N
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

/// Work a model keeps between the evaluations of one cascade (e.g. the ordering and symbolic factor of
/// the intact graph's stiffness). Opaque to callers; the model checks it fits the graph before use.
class StressSolverState {
 public:
  virtual ~StressSolverState() = default;
};

/// The outcome of one evaluation.
struct StressResult {
  std::vector<BondStress> bonds;                  ///< #bonds, same order as SupportGraph::bonds
  std::vector<std::vector<int>> falling_clusters; ///< fragment indices of each component with no anchor
  std::vector<double> displacements;              ///< 6 #nodes: translation (m) and rotation (rad) per node
  SolverReport report;                            ///< solver statistics
  /// The model's reusable solver work, handed on to the result of `reevaluate` (shared, not copied;
  /// may be null). Results sharing it must not be re-evaluated concurrently.
  std::shared_ptr<StressSolverState> solver_state;
};

/// A stress model. Implementations are stateless and thread-compatible.
class StressModel {
 public:
  virtual ~StressModel() = default;
  /// Registered name, e.g. "von-mises".
  [[nodiscard]] virtual std::string_view name() const = 0;
  /// True when the model breaks bonds only through the static solve of anchored components: with zero
  /// loads nothing breaks, and components without an anchor are never evaluated. The frame pipeline
  /// then skips the solve of a scene with no gravity or no anchors (result-neutral by this contract).
  [[nodiscard]] virtual bool driven_by_loads() const { return true; }
  /// Evaluates the intact graph. Errors for a bad material or bad loads.
  [[nodiscard]] virtual Result<StressResult> evaluate(const SupportGraph& graph, const Loads& loads,
                                                      const Material& material) const = 0;
  /// Re-evaluates after bonds were flagged broken in `previous`: components holding any node of
  /// `touched` are solved again (warm-started from `previous.displacements`), the others are copied.
  [[nodiscard]] virtual Result<StressResult> reevaluate(const SupportGraph& graph, const Loads& loads,
                                                        const Material& material, const StressResult& previous,
                                                        std::span<const int> touched) const = 0;
};


/// Error unless gravity and every point load are finite and refer to existing nodes.
Status check_loads(const Loads& loads, const SupportGraph& graph);

/// Error unless every force a model computed from the loads (6 per node: force, N, and moment, N m) is
/// finite: finite inputs can still overflow (gravity times a huge mass).
Status check_node_loads(std::span<const double> node_loads);

/// Whether every displacement and bond figure of `result` is finite; marks its report not converged
/// (and not finite) when one is not, so that no NaN or Inf is ever reported as a valid answer.
bool judge_finite(StressResult& result);

}  // namespace shatter
