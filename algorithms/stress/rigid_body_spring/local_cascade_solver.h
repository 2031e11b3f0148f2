#pragma once
/// The solver of "tresca-local" and "von-mises-local": the rigid-body-spring model whose cascade rounds
/// re-solve only the neighbourhood of their breaks.
///
/// Design note: an exact round of a cascade solves the whole structure again (cascade_solver.h), which
/// on a 10,000-bond wall costs several ms however few bonds broke, and a cascade has 10 to 20 rounds.
/// A break changes the forces mostly near it (the load finds its way round the gap through the bonds
/// next to it; farther away the change decays), so this solver solves every round on a window: the
/// nodes within `hops` intact bonds of the round's breaks. A cascade's start (the breaks it is given,
/// no displacements yet) is a round like the others, windowed around its breaks from the intact
/// structure's exact state under the same loads; the solver keeps that state (a structure at rest is
/// solved once, as a game solves it when the level loads), and a new solver solves it first, so the
/// result is the same either way. With `exact_start` the start is solved exactly instead. The nodes
/// just outside keep their displacements (a fixed boundary), anchored nodes stay fixed, and the
/// window's displacements are the exact solution of that local problem; the bonds with
/// an end in the window get new forces, the others keep theirs. Clusters cut loose fall exactly as in
/// the exact model (the components are found on the whole graph every round). When the window holds
/// a whole component, its solve is the exact one. What the window leaves out is an approximation with
/// a named size: `shatterbench accuracy --family cascade` reports the bonds it breaks differently from
/// the exact cascade and its stresses against an exact round (docs/stress.md, section 6).

#include "algorithms/stress/rigid_body_spring/bond_spring.h"
#include "algorithms/stress/rigid_body_spring/bond_stiffness_cache.h"
#include "algorithms/stress/rigid_body_spring/solved_systems.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_solver.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace shatter {

/// The nodes of a cascade round's window: `hops` intact bonds around the seeds.
struct CascadeWindow {
  std::vector<int> nodes;        ///< window nodes, in breadth-first order from the seeds
  std::vector<int> index;        ///< #nodes: position in `nodes`, or -1 outside the window
};

/// The free nodes within `hops` bonds (not `broken`) of the free `seeds`, walking only through free
/// nodes: a free node is one of an anchored component (`anchored_component`, per node) that is not
/// anchored itself. Anchored nodes have no unknowns, and a break's effect does not pass through them.
CascadeWindow cascade_window(const SupportGraph& graph, std::span<const std::uint8_t> broken,
                             std::span<const std::uint8_t> anchored_component, std::span<const int> seeds, int hops);

/// A rigid-body-spring solver of one structure whose cascade rounds are solved on a
/// window of `hops` bonds around their breaks (see the header note).
class LocalCascadeSolver final : public StressSolver {
 public:
  /// A solver for `graph` (which must outlive it unchanged) made of `material`; `hops` >= 1.
  /// With `exact_start`, a cascade's start is solved exactly (see the header note).
  LocalCascadeSolver(const SupportGraph& graph, const Material& material, Criterion criterion,
                     const SpringSolverSettings& settings, int hops, bool exact_start);
  ~LocalCascadeSolver() override;

  [[nodiscard]] const SupportGraph& graph() const override { return exact_.graph(); }
  /// The exact evaluation (StrengthCriterionSolver); kept as the structure at rest under `loads`.
  [[nodiscard]] Result<StressResult> evaluate(const Loads& loads) override;
  /// A `previous` without displacements (a cascade's start) is solved on the window around the ends of
  /// its broken bonds, from the structure at rest (exactly with `exact_start`, or without broken
  /// bonds); one with displacements is solved on the window around `touched` (the round's breaks).
  [[nodiscard]] Result<StressResult> reevaluate(const Loads& loads, const StressResult& previous,
                                                std::span<const int> touched) override;

 private:
  /// One round on the window of `hops_` bonds around `touched`, from `previous` (with displacements).
  [[nodiscard]] Result<StressResult> solve_window(const Loads& loads, const StressResult& previous,
                                                  std::span<const int> touched);

  StrengthCriterionSolver exact_;
  Material material_;
  Criterion criterion_;
  SpringSolverSettings settings_;
  int hops_;
  bool exact_start_;
  std::optional<Loads> rest_loads_;  // the loads of `rest_`, when it is kept
  StressResult rest_;                // the intact structure's exact state under rest_loads_
  std::optional<Loads> f_loads_;     // the loads of `f_`, when it is kept
  std::vector<double> f_;            // 6 #nodes: the node loads (node_loads) of f_loads_
  std::vector<std::array<int, 2>> bond_ends_;  // #bonds: each bond's nodes, as graph().bonds has them
  std::vector<std::uint8_t> anchors_;          // #nodes: 1 for an anchored node
  std::vector<std::uint8_t> broken_; // #bonds: a round's broken flags (scratch)
  std::vector<int> parent_;          // #nodes: a round's union-find (scratch)
  SolverMemory memory_;              // the windows' analyses and factors (a window seen again reuses them)
  std::vector<BondForces> forces_;   // #bonds: the forces of the last window's bonds (the others stale)
  BondStiffnessCache stiffness_;     // the springs and blocks of every bond a window reached
  std::vector<int> window_bonds_;    // a round's window bonds (scratch)
  std::vector<std::array<int, 2>> boundary_;  // a round's (window node, bond leaving the window) (scratch)
};

}  // namespace shatter
