#include "harness/pipeline/event/event_phases.h"

#include "algorithms/fracture/local_fracture.h"
#include "harness/pipeline/frame/frame_recorder.h"
#include "harness/pipeline/structure_response.h"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace shatter {
namespace {

/// Seed of the runtime fracture of hit fragment `k` of event `index` (docs/pipeline.md section 1).
std::uint64_t runtime_seed(const RunResult& r, int index, std::size_t k) {
  return r.runtime_seed + 1000003ULL * static_cast<std::uint64_t>(index) + k;
}

/// How many of `left` independent items (hit fragments to fracture, pieces to prepare) one step takes
/// when one thread takes `per_thread`: on one thread `per_thread`; on several, under `amortized` (whose
/// steps are spread over frames and must stay small) `per_thread` a thread, otherwise all of them in
/// one step, which runs in one frame anyway and lets the workers balance uneven items.
std::size_t items_per_step(const RunState& run, std::size_t left, std::size_t per_thread) {
  const auto threads = static_cast<std::size_t>(run.workers.threads());
  if (threads == 1) return std::min(left, per_thread);
  if (run.result.schedule == ScheduleMode::amortized) return std::min(left, per_thread * threads);
  return left;
}

/// Chooses the hit fragments (the first step of the phase). False when the impact reaches nothing.
bool select_hit_fragments(RunState& run, RuntimeEvent& e) {
  const Impact& impact = *e.impact;
  NearImpactOptions near;
  near.eligible = run.standing;
  near.cull_by_box = !run.options.no_skip;
  e.hit_fragments = fragments_near_impact(run.result.fragments, impact, near);
  e.selected = true;
  if (e.hit_fragments.empty()) {
    run.result.stages.skipped(Stage::runtime_fracture,
                              fmt::format("the impact at frame {} reaches no standing fragment (radius {} m): no "
                                          "runtime fracture, nothing after it",
                                          e.impact_frame, impact.radius));
    return false;
  }
  if (!run.options.no_skip && impact.radius > 0) {
    const auto standing = std::count(run.standing.begin(), run.standing.end(), std::uint8_t{1});
    run.result.stages.skipped(
        Stage::runtime_fracture,
        fmt::format("{} of {} standing fragments outside the impact radius: not fractured, not copied",
                    standing - static_cast<long>(e.hit_fragments.size()), standing));
  }
  return true;
}

/// The hit fragments a step takes (items_per_step), fractured at once (the first step also chooses
/// them; an impact that reaches nothing ends the event).
Status fracture_phase(RunState& run, RuntimeEvent& e) {
  StageTimer timer(run.result.frame_stages, Stage::runtime_fracture);
  if (!e.selected && !select_hit_fragments(run, e)) {
    e.phase = EventPhase::done;
    return {};
  }
  FractureParams params;
  params.fragments = run.runtime_fragments;
  params.impact = *e.impact;
  // The hit fragments checked at setup (run_setup.cpp); without those, the caller's memory: a fragment
  // broken again in a later repetition is not checked again.
  params.verdicts = run.checked_inputs ? run.checked_inputs.get() : run.options.verdicts;
  const std::size_t first = e.pieces.size();
  const std::size_t batch = items_per_step(run, e.hit_fragments.size() - first, 1);
  // Each fracture writes its own slot; the seeds follow the hit fragment's index, not the thread.
  std::vector<std::optional<Result<std::vector<Fragment>>>> fractured(batch);
  run.workers.for_each(batch, [&](std::size_t i) {
    FractureParams own = params;
    own.seed = runtime_seed(run.result, e.index, first + i);
    const Fragment& target = run.result.fragments[static_cast<std::size_t>(e.hit_fragments[first + i])];
    fractured[i].emplace(run.runtime_fracturer->fracture(target.mesh, own));
  });
  for (std::optional<Result<std::vector<Fragment>>>& pieces : fractured) {
    if (!*pieces)
      return Error{run.spec.name + ": runtime fracture at frame " + std::to_string(e.impact_frame) + ": " +
                   pieces->error().message};
    e.pieces.push_back(std::move(**pieces));
  }
  if (e.pieces.size() == e.hit_fragments.size()) {
    run.result.stages.ran(Stage::runtime_fracture);
    e.phase = phase_after(e.phase, event_route(run));
  }
  return {};
}

/// Every bond of a hit fragment breaks; the hit fragments leave the standing structure.
Status bond_update_phase(RunState& run, RuntimeEvent& e) {
  RunResult& r = run.result;
  if (run.plan.bonds) {
    StageTimer timer(r.frame_stages, Stage::bond_update);
    for (const int f : e.hit_fragments)
      for (const int b : r.graph.node_bonds[static_cast<std::size_t>(f)]) r.broken[static_cast<std::size_t>(b)] = 1;
    r.stages.ran(Stage::bond_update);
  } else {
    r.stages.skipped(Stage::bond_update, "no bonds (case needs)");
  }
  for (const int f : e.hit_fragments) run.standing[static_cast<std::size_t>(f)] = 0;
  e.phase = phase_after(e.phase, event_route(run));
  return {};
}

/// The whole stress cascade in one step.
Status stress_phase(RunState& run, RuntimeEvent& e) {
  if (Status s = solve_structure_stress(run, /*after_hit=*/true, run.result.frame_stages); !s) return s;
  e.phase = phase_after(e.phase, event_route(run));
  return {};
}

/// The standing components that lost every anchor leave the standing structure.
Status falling_clusters_phase(RunState& run, RuntimeEvent& e) {
  StageTimer timer(run.result.frame_stages, Stage::falling_clusters);
  e.falling = newly_falling_clusters(run);
  for (const std::vector<int>& cluster : e.falling)
    for (const int f : cluster) run.standing[static_cast<std::size_t>(f)] = 0;
  run.result.stages.ran(Stage::falling_clusters);
  e.phase = phase_after(e.phase, event_route(run));
  return {};
}

/// A batch of pieces, or one falling cluster, per step: bodies prepared, not yet in the world.
Status colliders_phase(RunState& run, RuntimeEvent& e) {
  StageTimer timer(run.result.frame_stages, Stage::colliders);
  const double density = run.spec.material.density;
  FrameRecorder* recorder = run.options.recorder;
  std::size_t total = 0;
  for (const auto& list : e.pieces) total += list.size();
  if (e.piece_bodies.size() < total) {
    // The next pieces (items_per_step), their hulls built at once.
    const std::size_t until = e.piece_bodies.size() + items_per_step(run, total - e.piece_bodies.size(), kColliderBatch);
    std::vector<const Fragment*> batch;
    std::vector<BodyOrigin> origins;  // only while recording
    std::size_t flat = 0;
    for (std::size_t k = 0; k < e.pieces.size(); ++k)
      for (std::size_t j = 0; j < e.pieces[k].size(); ++j) {
        if (flat >= e.piece_bodies.size() && flat < until) {
          batch.push_back(&e.pieces[k][j]);
          if (recorder) origins.push_back({RecordedBodyKind::piece, e.hit_fragments[k], static_cast<int>(j), {}});
        }
        ++flat;
      }
    const std::vector<int> bodies = run.world->prepare_fragments(batch, density, run.workers);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      e.piece_bodies.push_back(bodies[i]);
      if (recorder) recorder->body_made(bodies[i], std::move(origins[i]));
    }
  } else if (e.cluster_bodies.size() < e.falling.size()) {
    const std::vector<int>& cluster = e.falling[e.cluster_bodies.size()];
    std::vector<Fragment> members;
    for (const int f : cluster) members.push_back(run.result.fragments[static_cast<std::size_t>(f)]);
    e.cluster_bodies.push_back(run.world->prepare_cluster(members, density));
    if (recorder) recorder->body_made(e.cluster_bodies.back(), {RecordedBodyKind::cluster, -1, -1, cluster});
  }
  if (e.piece_bodies.size() == total && e.cluster_bodies.size() == e.falling.size())
    e.phase = phase_after(e.phase, event_route(run));
  return {};
}

/// The impulse's velocity change, shared by all of the event's pieces in proportion to their mass.
Vec3 event_velocity_change(const RunState& run, const RuntimeEvent& e) {
  const double density = run.spec.material.density;
  double total_mass = 0.0;
  for (const auto& list : e.pieces)
    for (const Fragment& p : list) total_mass += density * p.mass.volume;
  return total_mass > 0 ? Vec3(e.impact->direction * (e.impact->impulse / total_mass)) : Vec3::Zero();
}

/// Puts the event's prepared bodies into the world: the hit fragments' static bodies out and their
/// pieces in (the impulse given, small pieces start fading), then each falling cluster's static bodies
/// out and its compound in. Without a cap on new bodies per frame all go in now; with one, as many
/// whole hit fragments (then clusters) as fit under it in this frame, at least one a frame, the rest
/// in later steps, and on the run's last frame all that is left. True when every body is in.
bool replace_bodies(RunState& run, RuntimeEvent& e) {
  StageTimer timer(run.result.frame_stages, Stage::colliders);
  PhysicsWorld& world = *run.world;
  const double density = run.spec.material.density;
  const int cap = run.spec.schedule.max_new_bodies_per_frame;
  const bool last_frame = run.frame == run.settings.frames - 1;
  if (e.spawn_frame != run.frame) {
    e.spawn_frame = run.frame;
    e.spawned_in_frame = 0;
  }
  // The items (hit fragments, then clusters) this step puts in: [first, until).
  const std::size_t hits = e.hit_fragments.size();
  const std::size_t items = hits + e.falling.size();
  const std::size_t first = e.items_in_world;
  std::size_t until = first;
  while (until < items) {
    const int bodies = static_cast<int>(until < hits ? e.pieces[until].size() : 1);
    const bool fits = cap == 0 || last_frame || e.spawned_in_frame == 0 || e.spawned_in_frame + bodies <= cap;
    if (!fits) break;
    e.spawned_in_frame += bodies;
    ++until;
  }
  const std::size_t hits_until = std::min(until, hits);
  for (std::size_t k = first; k < hits_until; ++k) world.remove(run.static_body[static_cast<std::size_t>(e.hit_fragments[k])]);
  const Vec3 velocity_change = event_velocity_change(run, e);
  std::size_t flat = 0;
  for (std::size_t k = 0; k < first && k < hits; ++k) flat += e.pieces[k].size();
  for (std::size_t k = first; k < hits_until; ++k) {
    for (const Fragment& p : e.pieces[k]) {
      const int body = e.piece_bodies[flat++];
      world.insert(body);
      if (e.impact->impulse > 0) world.apply_impulse(body, velocity_change * (density * p.mass.volume), p.mass.centroid);
      if (run.spec.fade_out.enabled && p.mass.volume < run.spec.fade_out.max_volume)
        run.fading.push_back({body, run.frame});
    }
  }
  for (std::size_t k = std::max(first, hits); k < until; ++k) {
    for (const int f : e.falling[k - hits]) world.remove(run.static_body[static_cast<std::size_t>(f)]);
    world.insert(e.cluster_bodies[k - hits]);
  }
  e.items_in_world = until;
  if (until < items) {
    e.waits_until = run.frame + 1;
    return false;
  }
  return true;
}

/// Debris particles for the new cut area, at the pieces' centroids.
void spawn_debris(RunState& run, const RuntimeEvent& e) {
  RunResult& r = run.result;
  StageTimer timer(r.frame_stages, Stage::debris);
  double area = 0.0;
  std::vector<Vec3> origins;
  for (std::size_t k = 0; k < e.hit_fragments.size(); ++k) {
    area += new_cut_area(r.fragments[static_cast<std::size_t>(e.hit_fragments[k])], e.pieces[k]);
    for (const Fragment& p : e.pieces[k]) origins.push_back(p.mass.centroid);
  }
  r.particles_spawned +=
      run.debris->spawn(run.debris->count_for(area), origins, runtime_seed(r, e.index, 0) + 777767ULL);
  r.stages.ran(Stage::debris);
}

/// The event's result takes part in the world from this frame's physics step on; its fragments, pieces
/// and clusters join the run's result.
Status make_visible_phase(RunState& run, RuntimeEvent& e) {
  if (run.world && !replace_bodies(run, e)) return {};  // the rest of the bodies in a later frame
  if (run.debris) spawn_debris(run, e);
  RunResult& r = run.result;
  for (std::size_t k = 0; k < e.hit_fragments.size(); ++k) {
    r.hit.push_back(e.hit_fragments[k]);
    r.pieces.push_back(std::move(e.pieces[k]));
  }
  for (std::vector<int>& cluster : e.falling) r.falling_clusters.push_back(std::move(cluster));
  e.visible_frame = run.frame;
  e.phase = phase_after(e.phase, event_route(run));
  return {};
}

Status done_phase(RunState&, RuntimeEvent&) { return {}; }

using PhaseStep = Status (*)(RunState&, RuntimeEvent&);

/// One step function per phase, in EventPhase order.
constexpr std::array<PhaseStep, kEventPhaseCount> kPhaseSteps = {
    fracture_phase,         bond_update_phase, stress_phase, falling_clusters_phase,
    colliders_phase,        make_visible_phase, done_phase};

}  // namespace

EventRoute event_route(const RunState& run) {
  EventRoute route;
  route.bonds = run.plan.bonds;
  route.world = run.world != nullptr;
  return route;
}

Status run_event_step(RunState& run, RuntimeEvent& event) {
  return kPhaseSteps[static_cast<std::size_t>(event.phase)](run, event);
}

}  // namespace shatter
