// The frame pipeline: skipping is result-neutral, the cache returns what was computed, an impact that
// reaches nothing fractures nothing, and a stress cascade after an impact drops what lost its support.

#include "tests/support/builtin_registries.h"
#include "algorithms/stress/propagation.h"
#include "harness/cases/case_library.h"
#include "harness/pipeline/case_structure.h"
#include "harness/pipeline/destruction_run.h"

#include "tests/support/prepared_case.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>

namespace {

using namespace shatter;

using test::prepared;

RunResult run(const PreparedCase& p, RunOptions o) {
  o.partition_samples = 0;
  Result<RunResult> r = run_destruction(p, o, test::builtin_registries());
  INFO((r ? std::string() : r.error().message));
  REQUIRE(r);
  return std::move(*r);
}

bool same_mesh(const Mesh& a, const Mesh& b) {
  return a.vertices == b.vertices && a.triangles == b.triangles && a.tags == b.tags;
}

bool same_fragments(const std::vector<Fragment>& a, const std::vector<Fragment>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same_mesh(a[i].mesh, b[i].mesh) || a[i].mass.volume != b[i].mass.volume) return false;
  return true;
}

/// Fragments, bonds, broken bonds, hits, pieces and falling clusters are identical.
void require_same_outcome(const RunResult& a, const RunResult& b) {
  REQUIRE(same_fragments(a.fragments, b.fragments));
  REQUIRE(a.graph.bond_count() == b.graph.bond_count());
  for (int i = 0; i < a.graph.bond_count(); ++i) {
    const Bond& x = a.graph.bonds[static_cast<std::size_t>(i)];
    const Bond& y = b.graph.bonds[static_cast<std::size_t>(i)];
    REQUIRE(x.a == y.a);
    REQUIRE(x.b == y.b);
    REQUIRE(x.area == y.area);
  }
  REQUIRE(a.broken == b.broken);
  REQUIRE(a.hit == b.hit);
  REQUIRE(a.pieces.size() == b.pieces.size());
  for (std::size_t k = 0; k < a.pieces.size(); ++k) REQUIRE(same_fragments(a.pieces[k], b.pieces[k]));
  REQUIRE(a.falling_clusters == b.falling_clusters);
}

bool skipped(const RunResult& r, const std::string& stage, const std::string& words) {
  return std::any_of(r.stages.skips().begin(), r.stages.skips().end(), [&](const StageSkip& s) {
    return s.stage == stage && s.reason.find(words) != std::string::npos;
  });
}

/// The fixed-fixed beam (L = 4 m, slabs of 0.5 m) made weak enough that it stands intact but not once
/// the slab [1.5, 2] m is shot out: the tensile strength is 1.2 x the largest tensile stress of the
/// intact beam (at the clamped ends, w L^2 / 12 = 1.33 w m^2). What is left are two cantilevers: the
/// right one, 2 m long, has the root moment w 2^2 / 2 = 2 w m^2 > 1.6 w m^2 and breaks at its root; the
/// left one, 1.5 m, has 1.125 w m^2 and stands.
PreparedCase weak_fixed_beam() {
  PreparedCase p = prepared("fixed-beam");
  p.spec.impacts.front().impact.point = Vec3(1.75, 0.0, 0.25);
  p.spec.impacts.front().impact.radius = 0.0;
  Result<CaseStructure> s = build_case_structure(p.spec, test::builtin_registries());
  REQUIRE(s);
  auto model = test::builtin_registries().stress_models.create("von-mises");
  REQUIRE(model);
  Loads loads;
  loads.gravity = p.spec.gravity;
  auto intact = propagate(**model, s->graph, loads, p.spec.material);
  REQUIRE(intact);
  double peak = 0.0;
  for (const BondStress& b : intact->result.bonds)
    if (b.tensile) peak = std::max(peak, b.sigma);
  REQUIRE(peak > 0.0);
  p.spec.material.tensile_strength = 1.2 * peak;
  return p;
}

}  // namespace

TEST_CASE("pipeline: skipping and the forced full run give the same fragments, bonds and falling clusters",
          "[pipeline]") {
  SECTION("building: box culling of the impact and partial re-solves") {
    const PreparedCase p = prepared("building");
    RunOptions o;
    o.prefracture_fragments = 30;
    o.runtime_fragments = 5;
    o.frames = 15;
    const RunResult lean = run(p, o);
    o.no_skip = true;
    const RunResult full = run(p, o);
    require_same_outcome(lean, full);
    REQUIRE(!lean.hit.empty());
    REQUIRE(skipped(lean, "runtime_fracture", "outside the impact radius"));
    REQUIRE(lean.stages.skips().size() > full.stages.skips().size());
  }
  SECTION("a stress cascade after the impact: the partial re-solve and the run's kept solver drop the same clusters") {
    const PreparedCase p = weak_fixed_beam();
    // The case's exact model, and the windowed one, whose kept solver keeps the structure at rest.
    for (const char* model : {"", "von-mises-local"}) {
      INFO(model);
      RunOptions o;
      o.frames = 12;
      o.stress_model = model;
      const RunResult lean = run(p, o);
      o.no_skip = true;
      const RunResult full = run(p, o);
      require_same_outcome(lean, full);
      REQUIRE(lean.stress_rounds > 0);
      REQUIRE(!lean.falling_clusters.empty());
    }
  }
  SECTION("no gravity: the stress solve is skipped, and solving changes nothing") {
    PreparedCase p = prepared("cantilever");
    p.spec.gravity = Vec3::Zero();
    RunOptions o;
    o.frames = 3;
    const RunResult lean = run(p, o);
    o.no_skip = true;
    const RunResult full = run(p, o);
    require_same_outcome(lean, full);
    REQUIRE(skipped(lean, "stress", "no gravity"));
    const auto ran = full.stages.run();
    REQUIRE(std::find(ran.begin(), ran.end(), "stress") != ran.end());
  }
  SECTION("no anchors: everything falls whether or not the solve runs") {
    PreparedCase p = prepared("cantilever");
    p.spec.anchors.clear();
    RunOptions o;
    o.frames = 3;
    const RunResult lean = run(p, o);
    o.no_skip = true;
    const RunResult full = run(p, o);
    require_same_outcome(lean, full);
    REQUIRE(skipped(lean, "stress", "no anchors"));
    REQUIRE(lean.falling_clusters.size() == 1);  // the whole beam, one component
    REQUIRE(lean.hit.empty());                   // nothing standing is left to hit
  }
}

TEST_CASE("pipeline: a cascade after the impact breaks the longer cantilever's root and drops it", "[pipeline]") {
  const PreparedCase p = weak_fixed_beam();
  RunOptions o;
  o.frames = 12;
  const RunResult r = run(p, o);
  REQUIRE(r.graph.node_count() == 8);
  REQUIRE(r.hit == std::vector<int>{3});  // the slab [1.5, 2] m
  REQUIRE(r.stress_rounds >= 1);
  // The slabs [2, 2.5], [2.5, 3], [3, 3.5] m fall as one cluster; the left cantilever stands.
  REQUIRE(r.falling_clusters == std::vector<std::vector<int>>{{4, 5, 6}});
}

TEST_CASE("pipeline: a second run takes the pre-fracture from the cache, bit for bit", "[pipeline]") {
  const auto folder = std::filesystem::temp_directory_path() / "shatter_cache_test";
  std::filesystem::remove_all(folder);
  const PrefractureCache cache(folder);
  const PreparedCase p = prepared("building");
  RunOptions o;
  o.prefracture_fragments = 20;
  o.frames = 2;
  o.cache = &cache;
  const RunResult first = run(p, o);
  const RunResult second = run(p, o);
  REQUIRE_FALSE(first.cache_hit);
  REQUIRE(second.cache_hit);
  REQUIRE(skipped(second, "prefracture", "cache"));
  require_same_outcome(first, second);
  o.repetition = 1;  // another seed is another key
  REQUIRE_FALSE(run(p, o).cache_hit);
  std::filesystem::remove_all(folder);
}

TEST_CASE("pipeline: a damaged cache file is a miss, not an error", "[pipeline]") {
  const auto folder = std::filesystem::temp_directory_path() / "shatter_cache_damaged";
  std::filesystem::remove_all(folder);
  const PrefractureCache cache(folder);
  const PreparedCase p = prepared("building");
  PrefractureKey key;
  key.fracturer = "plane-slice";
  key.fragments = 10;
  key.seed = 1;
  std::vector<Fragment> none;
  REQUIRE(cache.store(p.solid.mesh, key, none));
  REQUIRE(cache.load(p.solid.mesh, key).has_value());
  const auto file = cache.file_for(p.solid.mesh, key);
  const auto size = std::filesystem::file_size(file);
  std::filesystem::resize_file(file, size - 1);
  REQUIRE_FALSE(cache.load(p.solid.mesh, key).has_value());
  std::filesystem::remove_all(folder);
}

TEST_CASE("pipeline: an impact that reaches nothing fractures nothing and says so", "[pipeline]") {
  PreparedCase p = prepared("building");
  p.spec.impacts.front().impact.point = Vec3(50, 50, 50);
  p.spec.impacts.front().impact.radius = 0.5;
  RunOptions o;
  o.prefracture_fragments = 20;
  o.frames = 12;
  const RunResult r = run(p, o);
  REQUIRE(r.hit.empty());
  REQUIRE(r.pieces.empty());
  REQUIRE(skipped(r, "runtime_fracture", "reaches no standing fragment"));
  const auto ran = r.stages.run();
  REQUIRE(std::find(ran.begin(), ran.end(), "runtime_fracture") == ran.end());
  REQUIRE(r.frame_ms.size() == 12);
}

TEST_CASE("pipeline: one frame runs the event in it, the case's needs switch stages off", "[pipeline]") {
  PreparedCase p = prepared("building");
  RunOptions o;
  o.prefracture_fragments = 20;
  o.frames = 1;  // the impact at frame 10 lands in the last (only) frame
  const RunResult one = run(p, o);
  REQUIRE(one.frame_ms.size() == 1);
  REQUIRE(one.event_frames == std::vector<int>{0});
  REQUIRE(!one.hit.empty());

  p.spec.needs.physics = false;
  p.spec.needs.colliders = false;
  p.spec.needs.stress = false;
  const RunResult lean = run(p, o);
  REQUIRE(skipped(lean, "physics", "not needed"));
  REQUIRE(skipped(lean, "stress", "not needed"));
  REQUIRE(lean.bodies == 0);
  REQUIRE(lean.hit == one.hit);
}
