// The decoupled supernodal solve against Eigen's SimplicialLDLT on the whole system, on a block wall
// large enough (2,898 unknowns) to split into blocks: displacements to 1e-9 relative, and the same
// cascade (bonds broken per round, falling clusters) exactly.
#include "algorithms/stress/propagation.h"
#include "algorithms/stress/rigid_body_spring/graph_stiffness.h"
#include "algorithms/stress/rigid_body_spring/linear_solve.h"
#include "algorithms/stress/rigid_body_spring/spring_system.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"
#include "fixtures/structures.h"
#include "tests/support/vector_difference.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

using namespace shatter;
using namespace shatter::fixtures;
using shatter::test::relative_difference;

namespace {

/// The bonds of the wall's block nearest (x, z).
std::vector<int> bonds_of_block_at(const SupportGraph& g, double x, double z) {
  int target = 0;
  double best = 1e300;
  for (int v = 0; v < g.node_count(); ++v) {
    const Vec3& c = g.nodes[static_cast<std::size_t>(v)].centroid;
    const double d = std::abs(c.x() - x) + std::abs(c.z() - z);
    if (d < best) best = d, target = v;
  }
  return g.node_bonds[static_cast<std::size_t>(target)];
}

/// The right-hand side of `stiffness`'s system (assembled from `g`) under gravity: each free node's
/// six loads at its unknowns.
Eigen::VectorXd gravity_loads(const SupportGraph& g, const GraphStiffness& stiffness) {
  const std::vector<double> loads = node_loads(g, Loads{}, Material{});
  Eigen::VectorXd f = Eigen::VectorXd::Zero(stiffness.unknowns());
  for (int v = 0; v < g.node_count(); ++v)
    if (const int i = stiffness.first_unknown(v); i >= 0)
      for (int q = 0; q < 6; ++q) f[i + q] = loads[6 * static_cast<std::size_t>(v) + static_cast<std::size_t>(q)];
  return f;
}

/// A solve of K u = f from u = 0 with a fresh memory, `u` its solution.
SolverReport solve_from_zero(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& f,
                             const SpringSolverSettings& settings, Eigen::VectorXd& u) {
  Eigen::SparseMatrix<double> taken = k;
  u = Eigen::VectorXd::Zero(k.cols());
  SolverMemory memory;
  return solve_linear(std::move(taken), f, u, settings, memory);
}

/// The relative residual of `u` formed in double either way the solver forms it: f - K u accumulated
/// into f (the refinement's form, Eigen's for an assigned f - k * u), and f minus the product K u.
std::pair<double, double> double_residuals(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& f,
                                           const Eigen::VectorXd& u) {
  const Eigen::VectorXd accumulated = f - k * u;
  const Eigen::VectorXd product = k * u;
  return {accumulated.norm() / f.norm(), (f - product).norm() / f.norm()};
}

SpringSolverSettings reference_settings() {
  SpringSolverSettings s;
  s.reference = true;
  return s;
}

}  // namespace

TEST_CASE("rigid-body-spring: decoupled supernodal solve matches SimplicialLDLT on a 23 x 22 wall", "[stress][von-mises][tresca]") {
  const SupportGraph g = block_wall(23, 22);
  for (const Criterion criterion : {Criterion::von_mises, Criterion::tresca}) {
    const StrengthCriterionModel fast(criterion);
    const StrengthCriterionModel reference(criterion, reference_settings());

    Result<StressResult> a = fast.evaluate(g, Loads{}, Material{});
    Result<StressResult> b = reference.evaluate(g, Loads{}, Material{});
    REQUIRE(a.ok());
    REQUIRE(b.ok());
    CHECK(a->report.unknowns == 6 * 22 * 23 - 6 * 23);  // the bottom row is anchored
    CHECK(a->report.converged);
    CHECK(a->report.residual < 1e-12);
    CHECK(b->report.residual < 1e-12);
    CHECK(relative_difference(a->displacements, b->displacements) < 1e-9);
    double worst = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < a->bonds.size(); ++i) {
      worst = std::max(worst, std::abs(a->bonds[i].utilization - b->bonds[i].utilization));
      peak = std::max(peak, b->bonds[i].utilization);
    }
    CHECK(worst < 1e-9 * peak);

    // The benchmark's cascade: a block of the second row knocked out, weak mortar.
    Material weak;
    weak.tensile_strength = 2e4;
    const std::vector<int> hole = bonds_of_block_at(g, 11.25 / 2, 0.75);  // as benchmarks/stress_benchmarks.cpp
    Result<PropagationResult> pa = propagate(fast, g, Loads{}, weak, hole);
    Result<PropagationResult> pb = propagate(reference, g, Loads{}, weak, hole);
    REQUIRE(pa.ok());
    REQUIRE(pb.ok());
    CHECK(pa->rounds >= 5);
    CHECK(pa->report.converged);
    CHECK(pa->break_order == pb->break_order);
    CHECK(pa->result.falling_clusters == pb->result.falling_clusters);
    CHECK(relative_difference(pa->result.displacements, pb->result.displacements) < 1e-9);
  }
}

TEST_CASE("rigid-body-spring: the cascade's reused solver state gives what a fresh solve gives", "[stress][von-mises]") {
  const SupportGraph g = block_wall(23, 22);
  const StrengthCriterionModel model(Criterion::von_mises);
  const std::unique_ptr<StressSolver> solver = model.make_solver(g, Material{});
  Result<StressResult> first = solver->evaluate(Loads{});
  REQUIRE(first.ok());

  // Knock out a block of the second row and a column above it, then re-solve from the first result
  // with the solver that made it (its state reused) and with a new solver (built afresh): the same
  // answer.
  StressResult next = first.value();
  std::vector<int> touched;
  for (const double z : {0.75, 1.25}) {
    const std::vector<int> bonds = bonds_of_block_at(g, 11.25 / 2, z);
    for (const int b : bonds) {
      next.bonds[static_cast<std::size_t>(b)].broken = true;
      touched.push_back(g.bonds[static_cast<std::size_t>(b)].a);
      touched.push_back(g.bonds[static_cast<std::size_t>(b)].b);
    }
  }
  Result<StressResult> reused = solver->reevaluate(Loads{}, next, touched);
  Result<StressResult> rebuilt = model.make_solver(g, Material{})->reevaluate(Loads{}, next, touched);
  REQUIRE(reused.ok());
  REQUIRE(rebuilt.ok());
  CHECK(reused->report.solves == 1);
  CHECK(reused->report.residual < 1e-12);
  CHECK(reused->falling_clusters == rebuilt->falling_clusters);
  CHECK(reused->falling_clusters.size() == 2);
  CHECK(relative_difference(reused->displacements, rebuilt->displacements) < 1e-12);
  for (std::size_t i = 0; i < reused->bonds.size(); ++i) {
    CHECK(reused->bonds[i].broken == rebuilt->bonds[i].broken);
    CHECK(std::abs(reused->bonds[i].utilization - rebuilt->bonds[i].utilization) <= 1e-12 * (1.0 + rebuilt->bonds[i].utilization));
  }
}

TEST_CASE("rigid-body-spring: the per-component path (CG blocks) gives the same cascade as the whole-graph one", "[stress][von-mises]") {
  const SupportGraph g = block_wall(8, 7);
  SpringSolverSettings cg;
  cg.direct_max_flops = 1.0;  // every block to CG: the whole-graph path steps aside
  cg.cg_tolerance = 1e-14;
  const StrengthCriterionModel iterative(Criterion::von_mises, cg);
  const StrengthCriterionModel direct(Criterion::von_mises);
  const StrengthCriterionModel reference(Criterion::von_mises, reference_settings());
  Material weak;
  weak.tensile_strength = 2e4;
  const std::vector<int> hole = bonds_of_block_at(g, 3.75 / 2, 0.75);
  for (const bool everything : {false, true}) {
    PropagationSettings settings;
    settings.resolve_everything = everything;
    Result<PropagationResult> pi = propagate(iterative, g, Loads{}, weak, hole, settings);
    Result<PropagationResult> pd = propagate(direct, g, Loads{}, weak, hole, settings);
    Result<PropagationResult> pr = propagate(reference, g, Loads{}, weak, hole, settings);
    REQUIRE(pi.ok());
    REQUIRE(pd.ok());
    REQUIRE(pr.ok());
    CHECK(pi->report.iterations > 0);
    CHECK(pd->report.iterations == 0);
    CHECK(pd->rounds >= 1);
    CHECK(pd->break_order == pr->break_order);
    CHECK(pi->break_order == pr->break_order);
    CHECK(pd->result.falling_clusters == pr->result.falling_clusters);
    CHECK(pi->result.falling_clusters == pr->result.falling_clusters);
    CHECK(relative_difference(pd->result.displacements, pr->result.displacements) < 1e-9);
  }
}

TEST_CASE("rigid-body-spring: refinement stops at its round-off floor without losing accuracy", "[stress][von-mises]") {
  SpringSolverSettings s;
  CHECK(refinement_pays(std::numeric_limits<double>::infinity(), 1e-13, s));  // the first step always runs
  CHECK(refinement_pays(1e-10, 1e-12, s));   // a gain of 100: another step may gain again
  CHECK_FALSE(refinement_pays(1e-13, 6e-14, s));  // a gain of 1.7: at the floor
  CHECK_FALSE(refinement_pays(1e-13, 0.0, s));    // exact
  // On the 23 x 22 wall, the early stop against every allowed step (a gain of 1 continues while the
  // residual falls at all, up to 4 steps): the same displacements to 1e-12, residuals both at round-off.
  const SupportGraph g = block_wall(23, 22);
  SpringSolverSettings every;
  every.refinement_gain = 1.0;
  every.refinement_steps = 4;
  const StrengthCriterionModel early(Criterion::von_mises);
  const StrengthCriterionModel all_steps(Criterion::von_mises, every);
  Loads pushed;
  pushed.point_loads.push_back(PointLoad{300, g.nodes[300].centroid, Vec3(2e4, 0.0, -2e4)});
  Result<StressResult> a = early.evaluate(g, pushed, Material{});
  Result<StressResult> b = all_steps.evaluate(g, pushed, Material{});
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  CHECK(relative_difference(a->displacements, b->displacements) < 1e-12);
  CHECK(a->report.residual < 4.0 * b->report.residual);
  // The first step did run: it takes the residual of the direct solve alone (round-off) down.
  SpringSolverSettings none;
  none.refinement_steps = 0;
  Result<StressResult> c = StrengthCriterionModel(Criterion::von_mises, none).evaluate(g, pushed, Material{});
  REQUIRE(c.ok());
  CHECK(a->report.residual < 0.8 * c->report.residual);
}

TEST_CASE("rigid-body-spring: the reported residual is that of the returned displacements", "[stress]") {
  // A refinement that stops early reports the residual it computed last; recomputed here from K, it
  // agrees bit for bit (a residual of the displacements before the last correction would not).
  const SupportGraph g = block_wall(12, 9);
  GraphStiffness stiffness(g, Material{});
  const std::vector<std::uint8_t> all(g.bonds.size(), 1), none(g.nodes.size(), 0);
  stiffness.assemble(all, none);
  const Eigen::SparseMatrix<double> k = stiffness.matrix();
  const Eigen::VectorXd f = gravity_loads(g, stiffness);
  for (const int steps : {0, 1, 2, 5}) {
    INFO("refinement steps " << steps);
    SpringSolverSettings settings;
    settings.refinement_steps = steps;
    Eigen::VectorXd u;
    const SolverReport report = solve_from_zero(k, f, settings, u);
    const auto [a, b] = double_residuals(k, f, u);
    INFO("reported " << report.residual << ", recomputed " << a << " and " << b);
    CHECK(report.residual > 0.0);
    CHECK((report.residual == a || report.residual == b));
  }
}

TEST_CASE("rigid-body-spring: a 3D block (6 x 6 node blocks) matches SimplicialLDLT, and so does its cascade", "[stress][von-mises]") {
  // A 2 x 1.5 x 2.5 m box cut into 4 x 3 x 5 slabs, anchored at its foot, under its own weight and an
  // off-axis push: every unknown couples, so K stays one block of 6 x 6 node blocks.
  const std::vector<Plane> cuts = [] {
    std::vector<Plane> planes = planes_at(0, even_cuts(-1.0, 1.0, 4));
    for (const Plane& p : planes_at(1, even_cuts(-0.75, 0.75, 3))) planes.push_back(p);
    for (const Plane& p : planes_at(2, even_cuts(0.0, 2.5, 5))) planes.push_back(p);
    return planes;
  }();
  const SupportGraph g = graph_of(sliced_box({2.0, 1.5, 2.5}, {0.0, 0.0, 1.25}, cuts),
                                  {box_region({-2, -2, -1}, {2, 2, 0.01})}, 2400.0);
  REQUIRE(g.node_count() == 60);
  Loads loads;
  int top = 0;
  for (int v = 0; v < g.node_count(); ++v)
    if (g.nodes[static_cast<std::size_t>(v)].centroid.z() > g.nodes[static_cast<std::size_t>(top)].centroid.z()) top = v;
  const Vec3 at = g.nodes[static_cast<std::size_t>(top)].centroid + Vec3(0.1, -0.2, 0.0);
  loads.point_loads.push_back(PointLoad{top, at, Vec3(3e5, 2e5, -1e5)});
  for (const Criterion criterion : {Criterion::von_mises, Criterion::tresca}) {
    const StrengthCriterionModel fast(criterion);
    const StrengthCriterionModel reference(criterion, reference_settings());
    Result<StressResult> a = fast.evaluate(g, loads, Material{});
    Result<StressResult> b = reference.evaluate(g, loads, Material{});
    REQUIRE(a.ok());
    REQUIRE(b.ok());
    CHECK(a->report.residual < 1e-12);
    CHECK(relative_difference(a->displacements, b->displacements) < 1e-9);
    Material weak;
    weak.tensile_strength = 2e5;
    Result<PropagationResult> pa = propagate(fast, g, loads, weak);
    Result<PropagationResult> pb = propagate(reference, g, loads, weak);
    REQUIRE(pa.ok());
    REQUIRE(pb.ok());
    INFO("rounds " << pa->rounds << ", falling clusters " << pa->result.falling_clusters.size());
    CHECK(pa->rounds >= 2);
    CHECK(!pa->result.falling_clusters.empty());
    CHECK(pa->break_order == pb->break_order);
    CHECK(pa->result.falling_clusters == pb->result.falling_clusters);
  }
}

namespace {

/// f - K u accumulated in long double, its norm: the test's own evaluation of a solve's residual.
double long_double_residual(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& f, const Eigen::VectorXd& u) {
  std::vector<long double> r(f.data(), f.data() + f.size());
  for (int j = 0; j < k.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, j); it; ++it)
      r[static_cast<std::size_t>(it.row())] -= static_cast<long double>(it.value()) * u[j];
  long double squares = 0.0L;
  for (const long double x : r) squares += x * x;
  return static_cast<double>(std::sqrt(squares));
}

}  // namespace

TEST_CASE("rigid-body-spring: near a mechanism, converged means the residual evaluated in long double is within tolerance",
          "[stress]") {
  // A 6 x 6 wall whose top two rows hang from the rest by one bond, its area and moments scaled by
  // `sliver`: the smaller the sliver, the larger the displacements under gravity, and the more K u
  // cancels f below double's round-off of |K| |u|.
  int extended_path = 0, refused = 0;
  for (const double sliver : {1e-4, 1e-6, 1e-7, 1e-8}) {
    SupportGraph g = block_wall(6, 6);
    std::vector<std::uint8_t> include(g.bonds.size(), 1);
    const std::vector<std::uint8_t> none(g.nodes.size(), 0);
    bool kept = false;
    for (std::size_t b = 0; b < g.bonds.size(); ++b) {
      Bond& bond = g.bonds[b];
      const bool across = (bond.a / 6 == 3 && bond.b / 6 == 4);  // between rows 3 and 4
      if (!across) continue;
      if (!kept) {
        kept = true;
        bond.area *= sliver;
        bond.moment_1 *= sliver;
        bond.moment_2 *= sliver;
        bond.polar_moment *= sliver;
      } else {
        include[b] = 0;
      }
    }
    REQUIRE(kept);
    GraphStiffness stiffness(g, Material{});
    stiffness.assemble(include, none);
    const Eigen::SparseMatrix<double> k = stiffness.matrix();
    const Eigen::VectorXd f = gravity_loads(g, stiffness);
    const SpringSolverSettings settings;
    Eigen::VectorXd u;
    const SolverReport report = solve_from_zero(k, f, settings, u);
    const auto [accumulated, product] = double_residuals(k, f, u);
    const double in_double = std::max(accumulated, product);  // either way the solver forms it
    const double in_long_double = long_double_residual(k, f, u) / f.norm();
    INFO("sliver " << sliver << ": reported " << report.residual << (report.converged ? " (converged)" : "")
                   << ", in double " << in_double << ", in long double " << in_long_double << ", |u| " << u.norm());
    // Converged exactly when the returned u's residual, evaluated without double's cancellation, is
    // within the tolerance; a solve that met it in double reports that residual, any other the long
    // double one.
    CHECK(report.converged == (in_long_double <= solve_tolerance(settings)));
    if (in_double <= solve_tolerance(settings)) {
      CHECK((report.residual == accumulated || report.residual == product));
    } else {
      CHECK(std::abs(report.residual - in_long_double) <= 1e-9 * in_long_double);
      if (report.converged) ++extended_path;  // refined with long double residuals into the tolerance
    }
    if (!report.converged) ++refused;
  }
  CHECK(extended_path > 0);  // the 1e-7 sliver: 1.5e-6 in double, 7.9e-7 after the refinement
  CHECK(refused > 0);        // the 1e-8 sliver: no double u is within the tolerance
}
