// The windowed cascade models ("tresca-local", "von-mises-local", local_cascade_solver.h): the window
// is every free node within `hops` bonds (Manhattan distance on a block wall), a window around the exact
// solution gives it back (the Dirichlet sub-problem of an exact state; beam theory on a cantilever), a
// window over the whole structure makes the exact cascade, nothing outside the window moves (a
// cascade's start included, windowed from the exact state at rest), and a kept solver gives what a new
// one gives.
#include "algorithms/bonds/graph_components.h"
#include "algorithms/stress/propagation.h"
#include "algorithms/stress/rigid_body_spring/local_cascade_model.h"
#include "algorithms/stress/rigid_body_spring/local_cascade_solver.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"
#include "fixtures/structures.h"
#include "tests/support/vector_difference.h"
#include "tests/support/builtin_registries.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

using namespace shatter;
using namespace shatter::fixtures;
using shatter::test::relative_difference;

namespace {

/// The node of block (i, k) of a block wall nx wide (blocks are made row by row).
int block(int nx, int i, int k) { return i + nx * k; }

std::unique_ptr<StressModel> local_model(int hops, Criterion criterion = Criterion::von_mises, bool exact_start = false) {
  return std::make_unique<LocalCascadeModel>(criterion, SpringSolverSettings{}, hops, exact_start);
}

/// The window of one bond around the four neighbours of block `loose` (4, 4) of a wall nx wide,
/// without the block itself (cut loose, it is in no anchored component).
std::set<int> one_bond_around_neighbours(const SupportGraph& g, int nx, int loose) {
  std::set<int> window;
  for (const int v : {block(nx, 3, 4), block(nx, 5, 4), block(nx, 4, 3), block(nx, 4, 5)})
    for (const int b : g.node_bonds[static_cast<std::size_t>(v)]) {
      window.insert(g.bonds[static_cast<std::size_t>(b)].a);
      window.insert(g.bonds[static_cast<std::size_t>(b)].b);
    }
  window.erase(loose);
  return window;
}

/// Checks that every node but `loose` outside `window` kept its displacements of `before` bit for bit;
/// returns the number of nodes that moved.
int moved_inside_only(const SupportGraph& g, const StressResult& after, const StressResult& before,
                      const std::set<int>& window, int loose) {
  int moved = 0;
  for (int v = 0; v < g.node_count(); ++v) {
    if (v == loose) continue;
    bool same = true;
    for (int k = 0; k < 6; ++k)
      same = same && after.displacements[static_cast<std::size_t>(6 * v + k)] == before.displacements[static_cast<std::size_t>(6 * v + k)];
    if (!window.count(v)) CHECK(same);
    moved += same ? 0 : 1;
  }
  return moved;
}

/// Whether two results are the same bit for bit: bonds (every figure), displacements, clusters.
bool same_result(const StressResult& x, const StressResult& y) {
  if (x.bonds.size() != y.bonds.size() || x.displacements != y.displacements || x.falling_clusters != y.falling_clusters)
    return false;
  for (std::size_t i = 0; i < x.bonds.size(); ++i) {
    const BondStress& a = x.bonds[i];
    const BondStress& b = y.bonds[i];
    if (a.broken != b.broken || a.normal_force != b.normal_force || a.shear_force != b.shear_force ||
        a.bending_moment != b.bending_moment || a.torsion != b.torsion || a.sigma != b.sigma || a.tau != b.tau ||
        a.utilization != b.utilization || a.tensile != b.tensile)
      return false;
  }
  return true;
}

}  // namespace

TEST_CASE("local cascade: the window is every free node within hops bonds of the seeds", "[stress][local-cascade]") {
  const int nx = 9, nz = 8;
  const SupportGraph g = block_wall(nx, nz);
  for (int v = 0; v < g.node_count(); ++v) REQUIRE(g.nodes[static_cast<std::size_t>(v)].anchored == (v < nx));
  const std::vector<std::uint8_t> intact(g.bonds.size(), 0);
  const std::vector<std::uint8_t> anchored_component(g.nodes.size(), 1);
  for (const auto& [seed_i, seed_k, hops] : {std::tuple{4, 4, 2}, std::tuple{4, 2, 4}, std::tuple{0, 1, 3}}) {
    const CascadeWindow w = cascade_window(g, intact, anchored_component, std::vector<int>{block(nx, seed_i, seed_k)}, hops);
    // On the grid of blocks, bond distance is the Manhattan distance; the anchored bottom row is no
    // part of a window, and a monotone path from a seed above it never needs to cross it.
    std::set<int> expected;
    for (int k = 1; k < nz; ++k)
      for (int i = 0; i < nx; ++i)
        if (std::abs(i - seed_i) + std::abs(k - seed_k) <= hops) expected.insert(block(nx, i, k));
    CHECK(std::set<int>(w.nodes.begin(), w.nodes.end()) == expected);
    CHECK(w.nodes.size() == expected.size());
    for (std::size_t j = 0; j < w.nodes.size(); ++j) CHECK(w.index[static_cast<std::size_t>(w.nodes[j])] == static_cast<int>(j));
  }
  // A broken bond is no path: cut the bonds above and to the right of block (4, 4), then the window of
  // one hop around it is the block and its left and lower neighbours.
  std::vector<std::uint8_t> broken(g.bonds.size(), 0);
  const int centre = block(nx, 4, 4);
  for (const int b : g.node_bonds[static_cast<std::size_t>(centre)]) {
    const int other = g.bonds[static_cast<std::size_t>(b)].a == centre ? g.bonds[static_cast<std::size_t>(b)].b : g.bonds[static_cast<std::size_t>(b)].a;
    if (other == block(nx, 5, 4) || other == block(nx, 4, 5)) broken[static_cast<std::size_t>(b)] = 1;
  }
  const CascadeWindow cut = cascade_window(g, broken, anchored_component, std::vector<int>{centre}, 1);
  CHECK(std::set<int>(cut.nodes.begin(), cut.nodes.end()) == std::set<int>{centre, block(nx, 3, 4), block(nx, 4, 3)});
  // A seed in a component without an anchor (a falling cluster) opens no window.
  std::vector<std::uint8_t> falling(g.nodes.size(), 1);
  falling[static_cast<std::size_t>(centre)] = 0;
  CHECK(cascade_window(g, intact, falling, std::vector<int>{centre}, 3).nodes.empty());
}

TEST_CASE("local cascade: a window around an exact state gives it back", "[stress][local-cascade]") {
  Material material;
  material.tensile_strength = material.compressive_strength = material.shear_strength = 1e12;  // nothing breaks
  SECTION("statically indeterminate: a block wall") {
    const SupportGraph g = block_wall(9, 8);
    const std::unique_ptr<StressSolver> exact = StrengthCriterionModel(Criterion::von_mises).make_solver(g, material);
    Result<StressResult> intact = exact->evaluate(Loads{});
    REQUIRE(intact.ok());
    const std::unique_ptr<StressSolver> local = local_model(2)->make_solver(g, material);
    Result<StressResult> again = local->reevaluate(Loads{}, *intact, std::vector<int>{block(9, 4, 4)});
    REQUIRE(again.ok());
    CHECK(again->report.converged);
    CHECK(again->report.solves == 1);
    CHECK(again->report.unknowns == 6 * 13);
    // The window's displacements solve its problem with the exact boundary: the exact ones.
    CHECK(relative_difference(again->displacements, intact->displacements) < 1e-9);
  }
  SECTION("statically determinate: a cantilever carries w (L - x)^2 / 2 at every bond") {
    const double length = 4.0, width = 0.5, height = 0.5, density = 2400.0;
    const SupportGraph g = graph_of(sliced_box({length, width, height}, {length / 2, 0, 0}, planes_at(0, even_cuts(0, length, 8))),
                                    {box_region({-1, -1, -1}, {0.001, 1, 1})}, density);
    const std::unique_ptr<StressSolver> exact = StrengthCriterionModel(Criterion::von_mises).make_solver(g, material);
    Result<StressResult> intact = exact->evaluate(Loads{});
    REQUIRE(intact.ok());
    const std::unique_ptr<StressSolver> local = local_model(1)->make_solver(g, material);
    Result<StressResult> again = local->reevaluate(Loads{}, *intact, std::vector<int>{4});
    REQUIRE(again.ok());
    const double w = density * 9.81 * width * height;
    for (const Bond& b : g.bonds) {
      const std::size_t i = static_cast<std::size_t>(&b - g.bonds.data());
      const double x = b.centroid.x();
      const double moment = w * (length - x) * (length - x) / 2.0;
      CHECK(std::abs(again->bonds[i].bending_moment - moment) < 1e-9 * moment);
    }
  }
}

TEST_CASE("local cascade: a window over the whole structure makes the exact cascade", "[stress][local-cascade]") {
  const SupportGraph g = block_wall(8, 7);
  Material weak;
  weak.tensile_strength = 2e4;
  const std::vector<int> hole = g.node_bonds[static_cast<std::size_t>(block(8, 4, 1))];
  Result<PropagationResult> exact = propagate(StrengthCriterionModel(Criterion::von_mises), g, Loads{}, weak, hole);
  Result<PropagationResult> local = propagate(*local_model(1000), g, Loads{}, weak, hole);
  REQUIRE(exact.ok());
  REQUIRE(local.ok());
  REQUIRE(exact->rounds >= 3);  // a real cascade
  CHECK(local->report.converged);
  CHECK(local->rounds == exact->rounds);
  REQUIRE(local->break_order.size() == exact->break_order.size());
  for (std::size_t r = 0; r < exact->break_order.size(); ++r) CHECK(local->break_order[r] == exact->break_order[r]);
  CHECK(local->result.falling_clusters == exact->result.falling_clusters);
  CHECK(relative_difference(local->result.displacements, exact->result.displacements) < 1e-9);
}

TEST_CASE("local cascade: nothing outside the window changes, and a block cut loose falls", "[stress][local-cascade]") {
  const int nx = 9, nz = 8;
  const SupportGraph g = block_wall(nx, nz);
  Material material;
  material.tensile_strength = material.compressive_strength = material.shear_strength = 1e12;
  const std::unique_ptr<StressSolver> exact = StrengthCriterionModel(Criterion::von_mises).make_solver(g, material);
  Result<StressResult> intact = exact->evaluate(Loads{});
  REQUIRE(intact.ok());
  // Every bond of block (4, 4) breaks: the block falls alone.
  StressResult next = *intact;
  const int loose = block(nx, 4, 4);
  std::vector<int> touched;
  std::vector<std::uint8_t> broken(g.bonds.size(), 0);
  for (const int b : g.node_bonds[static_cast<std::size_t>(loose)]) {
    next.bonds[static_cast<std::size_t>(b)].broken = true;
    broken[static_cast<std::size_t>(b)] = 1;
    touched.push_back(g.bonds[static_cast<std::size_t>(b)].a);
    touched.push_back(g.bonds[static_cast<std::size_t>(b)].b);
  }
  const std::unique_ptr<StressSolver> local = local_model(1)->make_solver(g, material);
  Result<StressResult> r = local->reevaluate(Loads{}, next, touched);
  REQUIRE(r.ok());
  CHECK(r->report.converged);
  // The falling clusters are those of the whole graph's components.
  CHECK(r->falling_clusters == falling_clusters(graph_components(g, broken)));
  CHECK(r->falling_clusters == std::vector<std::vector<int>>{{loose}});
  for (int k = 0; k < 6; ++k) CHECK(r->displacements[static_cast<std::size_t>(6 * loose + k)] == 0.0);
  // The window: the four neighbours (the loose block is in no anchored component) and one bond beyond.
  const std::set<int> window = one_bond_around_neighbours(g, nx, loose);
  CHECK(moved_inside_only(g, *r, *intact, window, loose) > 0);
  for (std::size_t b = 0; b < g.bonds.size(); ++b) {
    const Bond& bond = g.bonds[b];
    if (broken[b]) {
      CHECK(r->bonds[b].broken);
      CHECK(r->bonds[b].sigma == 0.0);
    } else if (!window.count(bond.a) && !window.count(bond.b)) {
      CHECK(r->bonds[b].sigma == intact->bonds[b].sigma);  // bit for bit
      CHECK(r->bonds[b].utilization == intact->bonds[b].utilization);
    }
  }
}

TEST_CASE("local cascade: a cascade's start is the window around its breaks, from the structure at rest", "[stress][local-cascade]") {
  const int nx = 9, nz = 8;
  const SupportGraph g = block_wall(nx, nz);
  Material material;
  material.tensile_strength = material.compressive_strength = material.shear_strength = 1e12;  // nothing breaks
  const std::unique_ptr<StressSolver> exact = StrengthCriterionModel(Criterion::von_mises).make_solver(g, material);
  Result<StressResult> intact = exact->evaluate(Loads{});
  REQUIRE(intact.ok());
  // The start of a cascade: the bonds of block (4, 4) given broken, no displacements.
  const int loose = block(nx, 4, 4);
  StressResult start;
  start.bonds.resize(g.bonds.size());
  for (const int b : g.node_bonds[static_cast<std::size_t>(loose)]) start.bonds[static_cast<std::size_t>(b)].broken = true;
  std::vector<int> all(static_cast<std::size_t>(g.node_count()));
  for (int v = 0; v < g.node_count(); ++v) all[static_cast<std::size_t>(v)] = v;
  const std::unique_ptr<StressSolver> local = local_model(1)->make_solver(g, material);
  Result<StressResult> r = local->reevaluate(Loads{}, start, all);
  REQUIRE(r.ok());
  CHECK(r->report.converged);
  CHECK(r->falling_clusters == std::vector<std::vector<int>>{{loose}});
  // The window: one bond around the loose block's neighbours (the block itself falls). Outside it the
  // displacements and bond figures are the exact intact ones, bit for bit; inside they moved.
  const std::set<int> window = one_bond_around_neighbours(g, nx, loose);
  CHECK(moved_inside_only(g, *r, *intact, window, loose) > 0);
  for (std::size_t b = 0; b < g.bonds.size(); ++b)
    if (!window.count(g.bonds[b].a) && !window.count(g.bonds[b].b) && g.bonds[b].a != loose && g.bonds[b].b != loose)
      CHECK(r->bonds[b].utilization == intact->bonds[b].utilization);

  // With exact_start the start is the exact model's, bit for bit.
  Result<StressResult> exact_first = exact->reevaluate(Loads{}, start, all);
  Result<StressResult> local_exact = local_model(1, Criterion::von_mises, true)->make_solver(g, material)->reevaluate(Loads{}, start, all);
  REQUIRE(exact_first.ok());
  REQUIRE(local_exact.ok());
  CHECK(same_result(*local_exact, *exact_first));
  CHECK_FALSE(same_result(*r, *exact_first));
}

TEST_CASE("local cascade: a kept solver gives what a new one gives, whatever it solved before", "[stress][local-cascade]") {
  const SupportGraph g = block_wall(12, 10);
  Material weak;
  weak.tensile_strength = 2e4;
  const std::vector<int> hole = g.node_bonds[static_cast<std::size_t>(block(12, 5, 1))];
  Loads heavy;
  heavy.gravity = Vec3(0.0, 0.0, -12.0);
  const std::unique_ptr<StressModel> model = local_model(2);
  const std::unique_ptr<StressSolver> kept = model->make_solver(g, weak);
  // Another load first (a structure at rest under other loads), then the cascade twice.
  REQUIRE(propagate(*kept, heavy, hole).ok());
  Result<PropagationResult> first = propagate(*kept, Loads{}, hole);
  Result<PropagationResult> again = propagate(*kept, Loads{}, hole);
  Result<PropagationResult> fresh = propagate(*model->make_solver(g, weak), Loads{}, hole);
  REQUIRE(first.ok());
  REQUIRE(again.ok());
  REQUIRE(fresh.ok());
  CHECK(fresh->rounds >= 2);
  CHECK(first->break_order == fresh->break_order);
  CHECK(again->break_order == fresh->break_order);
  CHECK(same_result(first->result, fresh->result));
  CHECK(same_result(again->result, fresh->result));
}

TEST_CASE("local cascade: both criteria are registered with their window size, which must be >= 1", "[stress][local-cascade][registry]") {
  const Registries r = test::builtin_registries();
  for (const char* name : {"tresca-local", "von-mises-local"}) {
    Result<std::unique_ptr<StressModel>> m = r.stress_models.create(name);
    REQUIRE(m.ok());
    CHECK((*m)->name() == name);
    REQUIRE(dynamic_cast<const LocalCascadeModel*>(m->get()) != nullptr);
    CHECK(dynamic_cast<const LocalCascadeModel*>(m->get())->hops() == LocalCascadeModel::kDefaultHops);
    Result<std::unique_ptr<StressModel>> two = r.stress_models.create(name, {{"hops", 2.0}});
    REQUIRE(two.ok());
    CHECK(dynamic_cast<const LocalCascadeModel*>(two->get())->hops() == 2);
    Result<std::unique_ptr<StressModel>> zero = r.stress_models.create(name, {{"hops", 0.0}});
    REQUIRE_FALSE(zero.ok());
    CHECK(zero.error().message.find("settings.hops") != std::string::npos);
    CHECK_FALSE(dynamic_cast<const LocalCascadeModel*>(m->get())->exact_start());
    Result<std::unique_ptr<StressModel>> exact_start = r.stress_models.create(name, {{"exact_start", 1.0}});
    REQUIRE(exact_start.ok());
    CHECK(dynamic_cast<const LocalCascadeModel*>(exact_start->get())->exact_start());
    CHECK_FALSE(r.stress_models.create(name, {{"exact_start", 2.0}}).ok());
  }
}
