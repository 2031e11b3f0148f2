// Stress models on block walls of about 100, 1,000 and 10,000 bonds: one evaluation, and the full
// cascade after a block at the foot of the wall is knocked out. Each runs again and again on the same
// wall with one solver kept for every iteration, as the pipeline keeps one per structure: an evaluation
// carries a point load that moves from block to block with every iteration (the same structure under
// new loads), so from the second iteration on the solver reuses the split and factors of the unchanged
// stiffness (solved_systems.h), and a cascade its kept cascade solver (cascade_solver.h); the "cold"
// variants make a new solver before every iteration (a graph seen for the first time). The cold cascade
// on small 3D boxes shows the other end: dense blocks, few rounds. evaluate_wall and cascade_wall run
// every stress model of the registries given to register_stress_benchmarks (benchmark_main.cpp); the
// cold variants measure the rigid-body-spring solver's reuse and name its models.
#include "algorithms/core/random.h"
#include "benchmarks/benchmark_families.h"
#include "algorithms/stress/propagation.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"
#include "harness/accuracy/cascade_accuracy.h"
#include "fixtures/structures.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace shatter;

/// Wall sides (blocks along x and up z) giving about 100, 1,000 and 10,000 bonds.
std::pair<int, int> wall_sides(int bonds) {
  if (bonds <= 100) return {8, 7};      // 97 bonds
  if (bonds <= 1000) return {23, 22};   // 967 bonds
  return {71, 71};                      // 9,940 bonds
}

/// Walls are built once per size (the plane slicing is not what is measured).
const SupportGraph& wall(int bonds) {
  static std::map<int, std::unique_ptr<SupportGraph>> cache;
  auto& slot = cache[bonds];
  if (!slot) {
    const auto [nx, nz] = wall_sides(bonds);
    slot = std::make_unique<SupportGraph>(fixtures::block_wall(nx, nz));
  }
  return *slot;
}

/// The bonds of the block in the second row nearest the middle of the wall: the impact's hole.
std::vector<int> hole(const SupportGraph& g) {
  int target = 0;
  double best = 1e300;
  double x_mid = 0.0;
  for (const SupportNode& n : g.nodes) x_mid = std::max(x_mid, n.centroid.x());
  for (int v = 0; v < g.node_count(); ++v) {
    const Vec3& c = g.nodes[static_cast<std::size_t>(v)].centroid;
    const double d = std::abs(c.x() - x_mid / 2) + std::abs(c.z() - 0.75);
    if (d < best) best = d, target = v;
  }
  return g.node_bonds[static_cast<std::size_t>(target)];
}

void add_counters(benchmark::State& state, const SupportGraph& g, const SolverReport& r) {
  state.counters["bonds"] = g.bond_count();
  state.counters["unknowns"] = r.unknowns;
  state.counters["iterations"] = r.iterations;
  state.counters["solves"] = r.solves;
  state.counters["residual"] = r.residual;
  state.counters["converged"] = r.converged ? 1 : 0;
}

/// Whether the iterations share one solver (warm) or each makes its own (cold).
enum class Pool { warm, cold };

/// The solver of the next iteration: `solver` again when warm, else a new one (made, and the old one
/// destroyed, outside the timing).
StressSolver& solver_for(benchmark::State& state, Pool pool, const StressModel& model, const SupportGraph& g,
                         const Material& material, std::unique_ptr<StressSolver>& solver) {
  if (pool == Pool::warm && solver) return *solver;
  state.PauseTiming();
  solver.reset();
  solver = model.make_solver(g, material);
  state.ResumeTiming();
  return *solver;
}

/// The built-in plugins, for the cold variants below (registered statically, by name).
const Registries& builtin() {
  static const Registries r = [] {
    Registries out;
    register_all(out);
    return out;
  }();
  return r;
}

void evaluate_wall(benchmark::State& state, const Registries& registries, const std::string& model_name,
                   Pool pool = Pool::warm) {
  const SupportGraph& g = wall(static_cast<int>(state.range(0)));
  const std::unique_ptr<StressModel> model = std::move(registries.stress_models.create(model_name).value());
  SolverReport report;
  Loads loads;
  loads.point_loads.push_back(PointLoad{});
  int step = 0;
  std::unique_ptr<StressSolver> solver;
  for (auto _ : state) {
    StressSolver& s = solver_for(state, pool, *model, g, Material{}, solver);
    PointLoad& p = loads.point_loads.front();  // 20 kN sideways and down, on the next block each time
    p.node = step++ % g.node_count();
    p.point = g.nodes[static_cast<std::size_t>(p.node)].centroid;
    p.force = Vec3(2e4, 0.0, -2e4);
    Result<StressResult> r = s.evaluate(loads);
    benchmark::DoNotOptimize(r);
    report = r->report;
  }
  add_counters(state, g, report);
}

/// The exact cascade the model states as its reference (StressModel::exact_cascade_reference), made
/// once per model, structure, hole and strength: what the model's outcome is set against.
const PropagationResult& exact_cascade(const StressModel& model, const SupportGraph& g, std::span<const int> broken,
                                       const Material& material) {
  static std::map<std::tuple<std::string, const SupportGraph*, std::vector<int>, double>, PropagationResult> cache;
  auto [slot, made] = cache.try_emplace(
      {std::string(model.name()), &g, std::vector<int>(broken.begin(), broken.end()), material.tensile_strength});
  if (made) {
    const std::unique_ptr<StressModel> reference = model.exact_cascade_reference();
    slot->second = propagate(reference ? *reference : model, g, Loads{}, material, broken).value();
  }
  return slot->second;
}

/// The cascade of `g` after `broken`, with mortar of `tensile_strength` (Pa), timed per iteration; the
/// counters set its outcome beside the exact cascade's (cascade_accuracy.h).
void run_cascade(benchmark::State& state, const std::unique_ptr<StressModel>& model, const SupportGraph& g,
                 std::span<const int> broken, double tensile_strength, Pool pool) {
  Material weak;  // a weak mortar, so that the hole makes something else fail
  weak.tensile_strength = tensile_strength;
  const PropagationResult& exact = exact_cascade(*model, g, broken, weak);
  PropagationResult last;
  std::unique_ptr<StressSolver> solver;
  for (auto _ : state) {
    StressSolver& s = solver_for(state, pool, *model, g, weak, solver);
    Result<PropagationResult> r = propagate(s, Loads{}, broken);
    benchmark::DoNotOptimize(r);
    last = std::move(r.value());
  }
  const CascadeComparison outcome = compare_cascades(last, exact, g.node_count());
  add_counters(state, g, last.report);
  state.counters["rounds"] = last.rounds;
  state.counters["broken"] = outcome.broken;
  state.counters["broken_exact"] = outcome.reference_broken;
  state.counters["broken_mismatch"] = outcome.broken_mismatch;
  state.counters["falling"] = outcome.falling;
  state.counters["falling_exact"] = outcome.reference_falling;
  state.counters["falling_mismatch"] = outcome.falling_mismatch;
}

void run_cascade(benchmark::State& state, const Registries& registries, const std::string& model_name,
                 const SupportGraph& g, std::span<const int> broken, double tensile_strength, Pool pool) {
  const std::unique_ptr<StressModel> model = std::move(registries.stress_models.create(model_name).value());
  run_cascade(state, model, g, broken, tensile_strength, pool);
}

void cascade_wall(benchmark::State& state, const Registries& registries, const std::string& model_name,
                  Pool pool = Pool::warm) {
  const SupportGraph& g = wall(static_cast<int>(state.range(0)));
  run_cascade(state, registries, model_name, g, hole(g), 2e4, pool);
}

/// A 2.5 m cube anchored at its foot, cut into 5 x 5 x 5 blocks along the axes (arg 0: 300 bonds, blocks
/// with zeros) or by 15 oblique planes (arg 1: 582 bonds, denser blocks); cascade_box_cold breaks the
/// bonds of the fragment nearest (0, 0, 0.75) under a weak mortar. The small 3D graphs of a game's
/// structures, where the stiffness has few structural zeros to drop.
const SupportGraph& box(int oblique) {
  static std::map<int, std::unique_ptr<SupportGraph>> cache;
  auto& slot = cache[oblique];
  if (!slot) {
    std::vector<Plane> cuts;
    if (oblique) {
      SplitMix64 random(5);
      for (int i = 0; i < 15; ++i) {
        Plane p;
        p.point = Vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(0, 2.5));
        p.normal = Vec3(random.uniform(-0.5, 0.5), random.uniform(-0.5, 0.5), random.uniform(-0.5, 0.5)).normalized();
        cuts.push_back(p);
      }
    } else {
      cuts = fixtures::planes_at(0, fixtures::even_cuts(-1.25, 1.25, 5));
      for (const Plane& p : fixtures::planes_at(1, fixtures::even_cuts(-1.25, 1.25, 5))) cuts.push_back(p);
      for (const Plane& p : fixtures::planes_at(2, fixtures::even_cuts(0.0, 2.5, 5))) cuts.push_back(p);
    }
    slot = std::make_unique<SupportGraph>(fixtures::graph_of(fixtures::sliced_box({2.5, 2.5, 2.5}, {0.0, 0.0, 1.25}, cuts),
                                                         {fixtures::box_region({-2, -2, -0.1}, {2, 2, 0.1})}, 2400.0));
  }
  return *slot;
}

void cascade_box_cold(benchmark::State& state, const char* model_name) {
  const SupportGraph& g = box(static_cast<int>(state.range(0)));
  int hole = 0;
  double best = 1e300;
  for (int v = 0; v < g.node_count(); ++v) {
    const Vec3& c = g.nodes[static_cast<std::size_t>(v)].centroid;
    const double d = std::abs(c.x()) + std::abs(c.y()) + std::abs(c.z() - 0.75);
    if (d < best) best = d, hole = v;
  }
  run_cascade(state, builtin(), model_name, g, g.node_bonds[static_cast<std::size_t>(hole)], 3e3, Pool::cold);
}

void evaluate_wall_cold(benchmark::State& state, const char* model_name) {
  evaluate_wall(state, builtin(), model_name, Pool::cold);
}
void cascade_wall_cold(benchmark::State& state, const char* model_name) {
  cascade_wall(state, builtin(), model_name, Pool::cold);
}

/// von-mises-local with a window of state.range(1) bonds on the wall of about state.range(0) bonds:
/// the window's time against the outcome it changes.
void cascade_wall_window(benchmark::State& state) {
  const SupportGraph& g = wall(static_cast<int>(state.range(0)));
  const std::unique_ptr<StressModel> model = std::move(
      builtin().stress_models.create("von-mises-local", {{"hops", static_cast<double>(state.range(1))}}).value());
  run_cascade(state, model, g, hole(g), 2e4, Pool::warm);
}

}  // namespace

namespace shatter {

void register_stress_benchmarks(const Registries& registries) {
  const Registries* reg = &registries;
  for (const std::string& model : registries.stress_models.names()) {
    std::string label = model;  // "connection-count" -> "connection_count", as the cold variants are named
    for (char& c : label)
      if (c == '-') c = '_';
    benchmark::RegisterBenchmark(("evaluate_wall/" + label).c_str(),
                                 [reg, model](benchmark::State& st) { evaluate_wall(st, *reg, model); })
        ->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("cascade_wall/" + label).c_str(),
                                 [reg, model](benchmark::State& st) { cascade_wall(st, *reg, model); })
        ->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
  }
}

}  // namespace shatter

BENCHMARK_CAPTURE(evaluate_wall_cold, tresca, "tresca")->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(evaluate_wall_cold, von_mises, "von-mises")->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(cascade_wall_cold, tresca, "tresca")->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(cascade_wall_cold, von_mises, "von-mises")->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(cascade_wall_window)->ArgsProduct({{1000, 10000}, {1, 2, 4, 8}})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(cascade_box_cold, von_mises, "von-mises")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
