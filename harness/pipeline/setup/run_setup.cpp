#include "harness/pipeline/setup/run_setup.h"

#include "algorithms/core/mesh.h"
#include "algorithms/core/solid_check.h"
#include "algorithms/fracture/local_fracture.h"
#include "harness/pipeline/frame/frame_recorder.h"
#include "harness/pipeline/setup/offline_structure.h"
#include "harness/pipeline/structure_response.h"
#include "harness/plugins/capable_fracturer.h"

#include <algorithm>
#include <string>
#include <utility>

namespace shatter {
namespace {

Status build_structure(RunState& run) {
  const Case& c = run.spec;
  const RunOptions& o = run.options;
  RunResult& r = run.result;
  OfflineSetupRequest request;
  request.fracturer = run.prefracturer.get();
  if (run.prefracturer)
    request.settings = settings_text(
        settings_for(run.prefracturer->name(), c.prefracture.fracturer, c.prefracture.settings));
  request.fragments = run.settings.prefracture_fragments;
  request.seed = c.prefracture.seed + o.repetition;
  request.cache = o.cache;
  request.read_cache = !o.no_skip;
  request.bonds = run.plan.bonds;
  Result<OfflineStructure> structure = build_offline_structure(c, run.solid, request, r.setup, r.stages);
  if (!structure) return structure.error();
  r.prefracture_seed = structure->key.seed;
  r.cache_hit = structure->cache_hit;
  r.fragments = std::move(structure->fragments);
  FractureMetricsOptions metrics;
  metrics.partition_samples = o.partition_samples;
  r.prefracture_error = fracture_metrics(run.solid.mesh, run.solid.mass, r.fragments, structure->key.fragments, metrics);
  run.anchored = std::move(structure->anchored);
  if (run.plan.bonds) {
    r.graph = std::move(structure->graph);
    r.broken.assign(r.graph.bonds.size(), 0);
  }
  run.standing.assign(r.fragments.size(), 1);
  return {};
}

/// The structure under its own weight before anything hits it: what cannot stand breaks and falls now.
Status settle(RunState& run) {
  RunResult& r = run.result;
  if (run.plan.bonds) {
    if (Status s = solve_structure_stress(run, /*after_hit=*/false, r.setup); !s) return s;
    StageTimer timer(r.setup, Stage::falling_clusters);
    for (std::vector<int>& cluster : newly_falling_clusters(run)) {
      for (const int f : cluster) run.standing[static_cast<std::size_t>(f)] = 0;
      r.falling_clusters.push_back(std::move(cluster));
    }
    r.stages.ran(Stage::falling_clusters);
  } else {
    // Without bonds nothing holds a fragment but an anchor.
    for (std::size_t f = 0; f < run.standing.size(); ++f) run.standing[f] = run.anchored[f];
    r.stages.skipped(Stage::stress, "not needed (case needs)");
    r.stages.skipped(Stage::falling_clusters, "no bonds: every fragment outside an anchor is loose");
  }
  return {};
}

/// The runtime fracturer checks its input (check_solid: closed, oriented, no self-intersection), and a
/// hit fragment's check is most of a runtime fracture's work after the slicing itself. A game checks
/// its assets while loading: the fragments the case's impacts reach (chosen as the event will choose
/// them) are checked here, on the workers, and the event's fractures find their verdicts. A fragment
/// the event reaches that is not among them, or that failed here, is checked in the frame as before.
void check_runtime_inputs(RunState& run) {
  if (run.options.no_skip || run.spec.impacts.empty()) return;
  RunResult& r = run.result;
  StageTimer timer(r.setup, Stage::runtime_fracture);
  NearImpactOptions near;
  near.eligible = run.standing;
  near.cull_by_box = true;
  std::vector<int> reached;
  for (const ImpactEvent& e : run.spec.impacts)
    for (const int f : fragments_near_impact(r.fragments, e.impact, near))
      if (std::find(reached.begin(), reached.end(), f) == reached.end()) reached.push_back(f);
  run.checked_inputs = std::make_unique<SelfIntersectionVerdicts>(reached.size() + kRememberedCleanMeshes);
  const std::string_view who = run.runtime_fracturer->name();
  run.workers.for_each(reached.size(), [&](std::size_t i) {
    (void)check_solid(r.fragments[static_cast<std::size_t>(reached[i])].mesh, who, run.checked_inputs.get());
  });
}

/// Contact manifolds for the world to allocate up front (PhysicsSettings::contact_pool_size): Bullet
/// keeps one per overlapping pair of bounding boxes, and the pairs peak when an event's pieces enter
/// the world. Fresh pieces of a slab-like solid overlap many neighbours' boxes (the tower's 412 bodies
/// at 100 x 25 made 24,500 pairs with Bullet's 0.05 m growth of the tree's boxes, fewer with the
/// world's 0.01 m: PhysicsSettings::broadphase_margin), so 64 per body expected at the peak: every
/// fragment, plus the runtime pieces of each fragment an impact reaches. Between Bullet's default and
/// 65,536 (70 MB).
int contact_pool_size(const RunState& run) {
  const std::vector<Fragment>& fragments = run.result.fragments;
  long bodies = static_cast<long>(fragments.size());
  for (const ImpactEvent& e : run.spec.impacts)
    bodies += static_cast<long>(fragments_near_impact(fragments, e.impact).size()) * std::max(run.runtime_fragments, 1);
  return static_cast<int>(std::clamp(64 * bodies, 4096L, 65536L));
}

/// The physics world: a ground at the solid's lowest point, every standing fragment a static body,
/// every fragment loose from the start a dynamic body, every falling cluster one compound.
void build_world(RunState& run) {
  RunResult& r = run.result;
  if (!run.plan.colliders) {
    r.stages.skipped(Stage::colliders, "not needed (case needs)");
    r.stages.skipped(Stage::physics, "not needed (case needs)");
    return;
  }
  StageTimer timer(r.setup, Stage::colliders);
  PhysicsSettings settings;
  settings.gravity = run.spec.gravity;
  settings.ground = true;
  settings.ground_z = bounding_box(run.solid.mesh).min.z();
  // A collider needs the outline, not every vertex: hulls of more than 64 points are reduced (about 42
  // support points) so that a piece of a scanned mesh costs Bullet what a piece of a box does.
  settings.max_hull_vertices = 64;
  settings.hull_vertex_budget = run.spec.colliders.vertex_budget;
  settings.contact_pool_size = contact_pool_size(run);
  run.world = std::make_unique<PhysicsWorld>(settings);
  run.world->set_workers(&run.workers);
  const double density = run.spec.material.density;
  FrameRecorder* recorder = run.options.recorder;
  run.static_body.assign(r.fragments.size(), -1);
  for (std::size_t f = 0; f < r.fragments.size(); ++f) {
    int body = -1;
    if (run.standing[f]) {
      body = run.static_body[f] = run.world->add_fragment(r.fragments[f], density, /*is_static=*/true);
    } else if (!run.plan.bonds) {
      body = run.world->add_fragment(r.fragments[f], density);
    }
    if (recorder && body >= 0) recorder->body_made(body, {RecordedBodyKind::fragment, static_cast<int>(f), -1, {}});
  }
  std::vector<Fragment> members;
  for (const std::vector<int>& cluster : r.falling_clusters) {
    members.clear();
    for (const int f : cluster) members.push_back(r.fragments[static_cast<std::size_t>(f)]);
    const int body = run.world->add_cluster(members, density);
    if (recorder) recorder->body_made(body, {RecordedBodyKind::cluster, -1, -1, cluster});
  }
  r.stages.ran(Stage::colliders);
}

}  // namespace

Status create_run_algorithms(RunState& run) {
  const Case& c = run.spec;
  const Registries& reg = run.registries;
  if (c.prefracture.explicit_planes()) {
    auto f = plane_cutter(reg.fracturers, c.prefracture.fracturer, c.prefracture.settings);
    if (!f) return Error{c.name + ": prefracture.planes: " + f.error().message};
    run.prefracturer = std::move(*f);
  } else {
    const std::string& name = run.settings.prefracture_fracturer;
    auto f = reg.fracturers.create(name, settings_for(name, c.prefracture.fracturer, c.prefracture.settings));
    if (!f) return Error{c.name + ": prefracture.fracturer: " + f.error().message};
    run.prefracturer = std::move(*f);
  }
  const std::string& runtime = run.settings.runtime_fracturer;
  auto rf = reg.fracturers.create(runtime, settings_for(runtime, c.runtime.fracturer, c.runtime.settings));
  if (!rf) return Error{c.name + ": runtime.fracturer: " + rf.error().message};
  run.runtime_fracturer = std::move(*rf);
  const std::string& model = run.settings.stress_model;
  auto m = reg.stress_models.create(model, settings_for(model, c.stress.model, c.stress.settings));
  if (!m) return Error{c.name + ": stress.model: " + m.error().message};
  run.stress_model = std::move(*m);
  run.runtime_fragments = run.settings.runtime_fragments;
  run.loads.gravity = c.gravity;
  return {};
}

Status run_setup(RunState& run) {
  if (Status s = create_run_algorithms(run); !s) return s;
  if (Status s = build_structure(run); !s) return s;
  if (Status s = settle(run); !s) return s;
  check_runtime_inputs(run);
  build_world(run);
  return {};
}

}  // namespace shatter
