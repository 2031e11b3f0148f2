#include "harness/pipeline/destruction_run.h"

#include "algorithms/bonds/graph_components.h"
#include "algorithms/fracture/local_fracture.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "algorithms/register_all.h"
#include "algorithms/stress/propagation.h"
#include "harness/cases/case_mesh.h"
#include "harness/pipeline/debris_field.h"
#include "harness/pipeline/physics/physics_world.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <memory>

namespace shatter {
namespace {

bool overlaps(const Aabb& a, const Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

#ifdef SHATTER_PLANTED_SLOWDOWN_SHARE
/// Test-only planted slowdown (CMake option SHATTER_PLANTED_SLOWDOWN): arithmetic for `share` of the
/// thread CPU time the step took. Under callgrind, whose slowdown is about the same per instruction
/// for this loop and for Bullet, that is about the same share of the stage's instructions.
void planted_work(double step_cpu_ms, double share) {
  const double until = thread_cpu_ms() + share * step_cpu_ms;
  volatile std::uint64_t x = 1;
  while (thread_cpu_ms() < until)
    for (int i = 0; i < 64; ++i) x = x * 6364136223846793005ULL + 1442695040888963407ULL;
}
#endif

/// The stages a case's needs imply (physics needs colliders; stress needs bonds; all need fragments).
struct StagePlan {
  bool fragments = true;
  bool bonds = true;
  bool stress = true;
  bool colliders = true;
  bool physics = true;
};

StagePlan plan_for(const Needs& n) {
  StagePlan p;
  p.physics = n.physics;
  p.colliders = n.colliders || n.physics;
  p.stress = n.stress;
  p.bonds = n.bonds || n.stress;
  p.fragments = true;  // every other stage works on fragments
  return p;
}

/// Pieces prepared as colliders per step of an amortized event.
constexpr std::size_t kColliderBatch = 4;

/// What a runtime event does next (docs/pipeline.md section 6); each phase is one or more steps.
enum class Phase { fracture, bond_update, stress, falling_clusters, colliders, swap, done };

/// One runtime event from its trigger until its result is in the world.
struct PendingEvent {
  const Impact* impact = nullptr;
  int index = 0;                             // event index, in impact order (seeds)
  int impact_frame = 0;
  int trigger_frame = 0;
  int visible_frame = -1;                    // frame of the swap step, -1 until then (or when nothing was hit)
  Phase phase = Phase::fracture;
  bool selected = false;                     // hit fragments chosen
  std::vector<int> hit;
  std::vector<std::vector<Fragment>> pieces; // per hit fragment fractured so far
  std::vector<std::vector<int>> falling;
  std::vector<int> piece_bodies;             // prepared bodies of the pieces, flat
  std::vector<int> cluster_bodies;           // prepared bodies of the falling clusters
};

/// Everything a run keeps between frames.
class Run {
 public:
  Run(const PreparedCase& prepared, const RunOptions& options) : c_(prepared.spec), solid_(prepared.solid), o_(options) {}

  Result<RunResult> execute();

 private:
  Status create_algorithms();
  Status setup();
  Status prefracture();
  Status build_bonds();
  Status settle();
  void make_colliders();
  Status step(PendingEvent& e);
  Status timed_step(PendingEvent& e);
  Status event_work(bool last_frame);
  void fade_out();
  Status stress_after(std::span<const int> hit, StageClocks& times);
  std::vector<std::vector<int>> newly_falling();
  void measure_runtime_error(std::span<const int> hit, std::span<const std::vector<Fragment>> pieces);

  const Case& c_;
  const Solid& solid_;
  const RunOptions& o_;
  StagePlan plan_;
  RunResult r_;

  std::unique_ptr<Fracturer> prefracturer_;
  std::unique_ptr<Fracturer> runtime_fracturer_;
  std::unique_ptr<StressModel> model_;
  std::unique_ptr<StressSolver> stress_solver_;  // the standing structure's, kept across every event
  int runtime_fragments_ = 0;
  Loads loads_;

  std::vector<std::uint8_t> standing_;     // per fragment: still part of the held structure
  std::vector<std::uint8_t> anchored_;     // per fragment: overlaps an anchor region
  std::vector<int> static_body_;           // per fragment: its static body id, or -1
  std::unique_ptr<PhysicsWorld> world_;

  ScheduleMode schedule_ = ScheduleMode::immediate;
  int frame_ = 0;                          // the frame being run
  std::deque<PendingEvent*> queue_;        // triggered events not yet done, in impact order
  struct Fading {
    int body;
    int visible_frame;
  };
  std::vector<Fading> fading_;             // runtime pieces fading out
  std::unique_ptr<DebrisField> debris_;    // particles (case key debris), or none
};

Status Run::create_algorithms() {
  const auto& reg = registries();
  if (!c_.prefracture.explicit_planes()) {
    const std::string& name = o_.prefracture_fracturer.empty() ? c_.prefracture.fracturer : o_.prefracture_fracturer;
    auto f = reg.fracturers.create(name);
    if (!f) return Error{c_.name + ": prefracture.fracturer: " + f.error().message};
    prefracturer_ = std::move(*f);
  }
  const std::string& runtime = o_.runtime_fracturer.empty() ? c_.runtime.fracturer : o_.runtime_fracturer;
  auto rf = reg.fracturers.create(runtime);
  if (!rf) return Error{c_.name + ": runtime.fracturer: " + rf.error().message};
  runtime_fracturer_ = std::move(*rf);
  const std::string& model = o_.stress_model.empty() ? c_.stress.model : o_.stress_model;
  auto m = reg.stress_models.create(model);
  if (!m) return Error{c_.name + ": stress.model: " + m.error().message};
  model_ = std::move(*m);
  runtime_fragments_ = o_.runtime_fragments > 0 ? o_.runtime_fragments : c_.runtime.fragments;
  loads_.gravity = c_.gravity;
  return {};
}

Status Run::prefracture() {
  PrefractureKey key;
  if (c_.prefracture.explicit_planes()) {
    key.fracturer = "plane-slice";
    key.planes = c_.prefracture.planes;
  } else {
    key.fracturer = std::string(prefracturer_->name());
    key.fragments = o_.prefracture_fragments > 0 ? o_.prefracture_fragments : c_.prefracture.fragments;
    key.seed = c_.prefracture.seed + o_.repetition;
  }
  r_.prefracture_seed = key.seed;
  {
    StageTimer timer(r_.setup, Stage::prefracture);
    if (o_.cache != nullptr && !o_.no_skip) {
      if (auto cached = o_.cache->load(solid_.mesh, key)) {
        r_.fragments = std::move(*cached);
        r_.cache_hit = true;
      }
    }
    if (!r_.cache_hit) {
      Result<std::vector<Fragment>> fragments = Error{""};
      if (c_.prefracture.explicit_planes()) {
        fragments = PlaneSliceFracturer().fracture_by_planes(solid_.mesh, c_.prefracture.planes);
        if (!fragments) return Error{c_.name + ": prefracture.planes: " + fragments.error().message};
      } else {
        FractureParams params;
        params.fragments = key.fragments;
        params.seed = key.seed;
        params.verdicts = o_.verdicts;
        fragments = prefracturer_->fracture(solid_.mesh, params);
        if (!fragments) return Error{c_.name + ": prefracture: " + fragments.error().message};
      }
      r_.fragments = std::move(*fragments);
    }
  }
  if (r_.cache_hit) {
    r_.stages.skipped(Stage::prefracture, "unchanged: taken from the cache (" + o_.cache->folder().string() + ")");
  } else {
    r_.stages.ran(Stage::prefracture);
    if (o_.cache != nullptr) o_.cache->store(solid_.mesh, key, r_.fragments);
  }
  FractureMetricsOptions metrics;
  metrics.partition_samples = o_.partition_samples;
  r_.prefracture_error = fracture_metrics(solid_.mesh, solid_.mass, r_.fragments, key.fragments, metrics);
  return {};
}

Status Run::build_bonds() {
  const std::size_t n = r_.fragments.size();
  anchored_.assign(n, 0);
  for (std::size_t i = 0; i < c_.anchors.size(); ++i) {
    bool touches = false;
    for (std::size_t f = 0; f < n; ++f) {
      if (overlaps(bounding_box(r_.fragments[f].mesh), c_.anchors[i])) {
        anchored_[f] = 1;
        touches = true;
      }
    }
    if (!touches) return Error{c_.name + ": anchors[" + std::to_string(i) + "]: the region touches no fragment"};
  }
  if (!plan_.bonds) {
    r_.stages.skipped(Stage::bonds, "not needed (case needs)");
    return {};
  }
  StageTimer timer(r_.setup, Stage::bonds);
  SupportGraphSettings settings;
  settings.density = c_.material.density;
  Result<SupportGraph> graph = build_support_graph(r_.fragments, c_.anchors, settings);
  if (!graph) return Error{c_.name + ": " + graph.error().message};
  r_.graph = std::move(*graph);
  r_.broken.assign(r_.graph.bonds.size(), 0);
  r_.stages.ran(Stage::bonds);
  return {};
}

/// Union-find over the intact bonds between standing fragments: the standing components that have
/// lost every anchor. Each cluster ascending; clusters in order of their smallest fragment.
std::vector<std::vector<int>> Run::newly_falling() {
  if (!plan_.bonds) return {};
  const GraphComponents parts = graph_components(r_.graph, r_.broken);
  std::vector<std::vector<int>> out;
  for (std::size_t k = 0; k < parts.nodes.size(); ++k) {
    if (parts.anchored[k]) continue;
    const std::vector<int>& nodes = parts.nodes[k];
    // Hit and fallen fragments are not standing; a standing fragment's component is all standing
    // (every bond to a hit fragment is broken, a fallen cluster was a whole component).
    if (!standing_[static_cast<std::size_t>(nodes.front())]) continue;
    out.push_back(nodes);
  }
  return out;
}

Status Run::stress_after(std::span<const int> hit, StageClocks& times) {
  if (!plan_.stress) {
    r_.stages.skipped(Stage::stress, "not needed (case needs)");
    return {};
  }
  if (!o_.no_skip && model_->driven_by_loads()) {
    if (loads_.gravity.isZero(0.0)) {
      r_.stages.skipped(Stage::stress, "no gravity: nothing loads the structure, no bond can fail");
      return {};
    }
    if (c_.anchors.empty()) {
      r_.stages.skipped(Stage::stress, "no anchors: every component falls, none is solved");
      return {};
    }
  }
  StageTimer timer(times, Stage::stress);
  std::vector<int> broken;
  for (std::size_t b = 0; b < r_.broken.size(); ++b)
    if (r_.broken[b]) broken.push_back(static_cast<int>(b));
  PropagationSettings settings;
  settings.resolve_everything = o_.no_skip;
  if (!stress_solver_) stress_solver_ = model_->make_solver(r_.graph, c_.material);
  auto p = propagate(*stress_solver_, loads_, broken, settings);
  if (!p) return Error{c_.name + ": stress: " + p.error().message};
  for (std::size_t b = 0; b < r_.broken.size(); ++b)
    if (p->result.bonds[b].broken) r_.broken[b] = 1;
  r_.stress_rounds += p->rounds;
  r_.solver.solves += p->report.solves;
  r_.solver.iterations += p->report.iterations;
  r_.solver.converged = r_.solver.converged && p->report.converged;
  r_.solver.residual = std::max(r_.solver.residual, p->report.residual);
  r_.solver.unknowns = std::max(r_.solver.unknowns, p->report.unknowns);
  r_.stages.ran(Stage::stress);
  if (!hit.empty() && !o_.no_skip)
    r_.stages.skipped(Stage::stress, "components no broken bond touched: not re-solved between rounds");
  return {};
}

Status Run::settle() {
  // The structure under its own weight before anything hits it: what cannot stand breaks and falls now.
  if (plan_.bonds) {
    if (Status s = stress_after({}, r_.setup); !s) return s;
    StageTimer timer(r_.setup, Stage::falling_clusters);
    for (std::vector<int>& cluster : newly_falling()) {
      for (const int f : cluster) standing_[static_cast<std::size_t>(f)] = 0;
      r_.falling_clusters.push_back(std::move(cluster));
    }
    r_.stages.ran(Stage::falling_clusters);
  } else {
    // Without bonds nothing holds a fragment but an anchor.
    for (std::size_t f = 0; f < standing_.size(); ++f) standing_[f] = anchored_[f];
    r_.stages.skipped(Stage::stress, "not needed (case needs)");
    r_.stages.skipped(Stage::falling_clusters, "no bonds: every fragment outside an anchor is loose");
  }
  return {};
}

void Run::make_colliders() {
  if (!plan_.colliders) {
    r_.stages.skipped(Stage::colliders, "not needed (case needs)");
    r_.stages.skipped(Stage::physics, "not needed (case needs)");
    return;
  }
  StageTimer timer(r_.setup, Stage::colliders);
  PhysicsSettings settings;
  settings.gravity = c_.gravity;
  settings.ground = true;
  settings.ground_z = bounding_box(solid_.mesh).min.z();
  // A collider needs the outline, not every vertex: hulls of more than 64 points are reduced (about 42
  // support points) so that a piece of a scanned mesh costs Bullet what a piece of a box does.
  settings.max_hull_vertices = 64;
  world_ = std::make_unique<PhysicsWorld>(settings);
  const double density = c_.material.density;
  static_body_.assign(r_.fragments.size(), -1);
  for (std::size_t f = 0; f < r_.fragments.size(); ++f) {
    if (standing_[f]) {
      static_body_[f] = world_->add_fragment(r_.fragments[f], density, /*is_static=*/true);
    } else if (!plan_.bonds) {
      world_->add_fragment(r_.fragments[f], density);
    }
  }
  std::vector<Fragment> members;
  for (const std::vector<int>& cluster : r_.falling_clusters) {
    members.clear();
    for (const int f : cluster) members.push_back(r_.fragments[static_cast<std::size_t>(f)]);
    world_->add_cluster(members, density);
  }
  r_.stages.ran(Stage::colliders);
}

Status Run::setup() {
  if (Status s = create_algorithms(); !s) return s;
  if (Status s = prefracture(); !s) return s;
  standing_.assign(r_.fragments.size(), 1);
  if (Status s = build_bonds(); !s) return s;
  if (Status s = settle(); !s) return s;
  make_colliders();
  return {};
}

void Run::measure_runtime_error(std::span<const int> hit, std::span<const std::vector<Fragment>> pieces) {
  RuntimeFractureError& e = r_.runtime_error;
  FractureMetricsOptions options;
  options.partition_samples = o_.partition_samples;
  for (std::size_t k = 0; k < hit.size(); ++k) {
    const Fragment& parent = r_.fragments[static_cast<std::size_t>(hit[k])];
    const FractureMetrics m = fracture_metrics(parent.mesh, parent.mass, pieces[k], runtime_fragments_, options);
    e.volume_error = std::max(e.volume_error, m.volume_error);
    e.partition_error = std::max(e.partition_error, m.partition_error);
    e.all_closed = e.all_closed && m.all_closed;
    if (e.pieces == 0 || m.min_fragment_volume < e.min_fragment_volume) e.min_fragment_volume = m.min_fragment_volume;
    e.pieces += static_cast<int>(pieces[k].size());
    ++e.hit;
  }
}

Status Run::step(PendingEvent& e) {
  StageClocks& t = r_.frame_stages;
  const Impact& impact = *e.impact;
  switch (e.phase) {
    case Phase::fracture: {
      StageTimer timer(t, Stage::runtime_fracture);
      if (!e.selected) {
        NearImpactOptions near;
        near.eligible = standing_;
        near.cull_by_box = !o_.no_skip;
        e.hit = fragments_near_impact(r_.fragments, impact, near);
        e.selected = true;
        if (e.hit.empty()) {
          r_.stages.skipped(Stage::runtime_fracture,
                            fmt::format("the impact at frame {} reaches no standing fragment (radius {} m): no "
                                        "runtime fracture, nothing after it",
                                        e.impact_frame, impact.radius));
          e.phase = Phase::done;
          return {};
        }
        if (!o_.no_skip && impact.radius > 0) {
          const auto standing = std::count(standing_.begin(), standing_.end(), std::uint8_t{1});
          r_.stages.skipped(Stage::runtime_fracture,
                            fmt::format("{} of {} standing fragments outside the impact radius: not fractured, not copied",
                                        standing - static_cast<long>(e.hit.size()), standing));
        }
      }
      // One hit fragment per step.
      FractureParams params;
      params.fragments = runtime_fragments_;
      params.impact = impact;
      params.verdicts = o_.verdicts;
      const std::size_t k = e.pieces.size();
      params.seed = r_.runtime_seed + 1000003ULL * static_cast<std::uint64_t>(e.index) + k;
      auto p = runtime_fracturer_->fracture(r_.fragments[static_cast<std::size_t>(e.hit[k])].mesh, params);
      if (!p) return Error{c_.name + ": runtime fracture at frame " + std::to_string(e.impact_frame) + ": " + p.error().message};
      e.pieces.push_back(std::move(*p));
      if (e.pieces.size() == e.hit.size()) {
        r_.stages.ran(Stage::runtime_fracture);
        e.phase = Phase::bond_update;
      }
      return {};
    }
    case Phase::bond_update:
      if (plan_.bonds) {
        StageTimer timer(t, Stage::bond_update);
        for (const int f : e.hit)
          for (const int b : r_.graph.node_bonds[static_cast<std::size_t>(f)]) r_.broken[static_cast<std::size_t>(b)] = 1;
        r_.stages.ran(Stage::bond_update);
      } else {
        r_.stages.skipped(Stage::bond_update, "no bonds (case needs)");
      }
      for (const int f : e.hit) standing_[static_cast<std::size_t>(f)] = 0;
      e.phase = plan_.bonds ? Phase::stress : (world_ ? Phase::colliders : Phase::swap);
      return {};
    case Phase::stress:
      if (Status s = stress_after(e.hit, t); !s) return s;
      e.phase = Phase::falling_clusters;
      return {};
    case Phase::falling_clusters: {
      StageTimer timer(t, Stage::falling_clusters);
      e.falling = newly_falling();
      for (const std::vector<int>& cluster : e.falling)
        for (const int f : cluster) standing_[static_cast<std::size_t>(f)] = 0;
      r_.stages.ran(Stage::falling_clusters);
      e.phase = world_ ? Phase::colliders : Phase::swap;
      return {};
    }
    case Phase::colliders: {
      // A batch of pieces, or one falling cluster, per step; prepared, not yet in the world.
      StageTimer timer(t, Stage::colliders);
      const double density = c_.material.density;
      std::size_t total = 0;
      for (const auto& list : e.pieces) total += list.size();
      if (e.piece_bodies.size() < total) {
        std::size_t flat = 0;
        const std::size_t until = std::min(total, e.piece_bodies.size() + kColliderBatch);
        for (const auto& list : e.pieces)
          for (const Fragment& p : list) {
            if (flat >= e.piece_bodies.size() && flat < until) e.piece_bodies.push_back(world_->prepare_fragment(p, density));
            ++flat;
          }
      } else if (e.cluster_bodies.size() < e.falling.size()) {
        std::vector<Fragment> members;
        for (const int f : e.falling[e.cluster_bodies.size()]) members.push_back(r_.fragments[static_cast<std::size_t>(f)]);
        e.cluster_bodies.push_back(world_->prepare_cluster(members, density));
      }
      if (e.piece_bodies.size() == total && e.cluster_bodies.size() == e.falling.size()) e.phase = Phase::swap;
      return {};
    }
    case Phase::swap: {
      // The event's result takes part in the world: hit and falling static bodies out, new bodies in.
      if (world_) {
        StageTimer timer(t, Stage::colliders);
        const double density = c_.material.density;
        for (const int f : e.hit) world_->remove(static_body_[static_cast<std::size_t>(f)]);
        double total_mass = 0.0;
        for (const auto& list : e.pieces)
          for (const Fragment& p : list) total_mass += density * p.mass.volume;
        const Vec3 velocity_change =
            total_mass > 0 ? Vec3(impact.direction * (impact.impulse / total_mass)) : Vec3::Zero();
        std::size_t flat = 0;
        for (const auto& list : e.pieces) {
          for (const Fragment& p : list) {
            const int body = e.piece_bodies[flat++];
            world_->insert(body);
            if (impact.impulse > 0) world_->apply_impulse(body, velocity_change * (density * p.mass.volume), p.mass.centroid);
            if (c_.fade_out.enabled && p.mass.volume < c_.fade_out.max_volume) fading_.push_back({body, frame_});
          }
        }
        for (std::size_t k = 0; k < e.falling.size(); ++k) {
          for (const int f : e.falling[k]) world_->remove(static_body_[static_cast<std::size_t>(f)]);
          world_->insert(e.cluster_bodies[k]);
        }
      }
      if (debris_) {
        StageTimer timer(t, Stage::debris);
        double area = 0.0;
        std::vector<Vec3> origins;
        for (std::size_t k = 0; k < e.hit.size(); ++k) {
          area += new_cut_area(r_.fragments[static_cast<std::size_t>(e.hit[k])], e.pieces[k]);
          for (const Fragment& p : e.pieces[k]) origins.push_back(p.mass.centroid);
        }
        r_.particles_spawned += debris_->spawn(debris_->count_for(area), origins,
                                               r_.runtime_seed + 1000003ULL * static_cast<std::uint64_t>(e.index) + 777767ULL);
        r_.stages.ran(Stage::debris);
      }
      for (std::size_t k = 0; k < e.hit.size(); ++k) {
        r_.hit.push_back(e.hit[k]);
        r_.pieces.push_back(std::move(e.pieces[k]));
      }
      for (std::vector<int>& cluster : e.falling) r_.falling_clusters.push_back(std::move(cluster));
      e.visible_frame = frame_;
      e.phase = Phase::done;
      return {};
    }
    case Phase::done:
      return {};
  }
  return {};
}

Status Run::timed_step(PendingEvent& e) {
  const auto start = std::chrono::steady_clock::now();
  Status s = step(e);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  r_.step_ms.push_back(ms);
  r_.largest_step_ms = std::max(r_.largest_step_ms, ms);
  r_.frame_work_ms[static_cast<std::size_t>(frame_)] += ms;
  return s;
}

Status Run::event_work(bool last_frame) {
  const ScheduleSpec& spec = c_.schedule;
  if (schedule_ == ScheduleMode::amortized) {
    // At least one step a frame; no step starts once the frame's event work reaches the budget (the
    // last frame finishes what is left): a frame spends at most the budget plus one step.
    bool first = true;
    while (!queue_.empty() && queue_.front()->impact_frame <= frame_) {
      if (!first && !last_frame && r_.frame_work_ms[static_cast<std::size_t>(frame_)] >= spec.work_budget_ms) break;
      if (Status s = timed_step(*queue_.front()); !s) return s;
      first = false;
      if (queue_.front()->phase == Phase::done) queue_.pop_front();
    }
    return {};
  }
  if (schedule_ == ScheduleMode::prefetch) {
    // Every triggered event's fracture now (the projectile is in flight); the rest when it lands.
    for (PendingEvent* e : queue_)
      while (e->phase == Phase::fracture)
        if (Status s = timed_step(*e); !s) return s;
  }
  while (!queue_.empty() && queue_.front()->impact_frame <= frame_) {
    while (queue_.front()->phase != Phase::done)
      if (Status s = timed_step(*queue_.front()); !s) return s;
    queue_.pop_front();
  }
  return {};
}

void Run::fade_out() {
  if (fading_.empty()) return;
  StageTimer timer(r_.frame_stages, Stage::colliders);
  const int lifetime = c_.fade_out.lifetime_frames;
  std::size_t kept = 0;
  for (const Fading& f : fading_) {
    const int age = frame_ - f.visible_frame;
    if (age <= 0) {
      fading_[kept++] = f;
    } else if (age >= lifetime) {
      world_->remove(f.body);
      ++r_.faded;
    } else {
      world_->set_scale(f.body, 1.0 - static_cast<double>(age) / lifetime);
      fading_[kept++] = f;
    }
  }
  fading_.resize(kept);
}

/// Trigger to visible at 60 Hz: each frame lasts max(its wall time, 1/60 s). Summed in units of
/// 1/60 ms so that frames within the period add up exactly (3 frames: 50 ms, not 50.000000000000007).
double paced_ms(const std::vector<double>& frame_ms, int first, int last) {
  double sixtieths = 0.0;
  for (int f = first; f <= last; ++f) sixtieths += std::max(frame_ms[static_cast<std::size_t>(f)] * 60.0, 1000.0);
  return sixtieths / 60.0;
}

Result<RunResult> Run::execute() {
  plan_ = plan_for(c_.needs);
  instruction_marks::set_frame(-1);
  if (Status s = setup(); !s) return s.error();
  r_.runtime_seed = c_.prefracture.seed + o_.repetition;
  schedule_ = o_.schedule.value_or(c_.schedule.mode);
  r_.schedule = schedule_;

  const int frames = o_.frames > 0 ? o_.frames : c_.frames;
  r_.frame_ms.assign(static_cast<std::size_t>(frames), 0.0);
  r_.frame_cpu_ms.assign(static_cast<std::size_t>(frames), 0.0);
  r_.frame_work_ms.assign(static_cast<std::size_t>(frames), 0.0);
  r_.frame_bodies.assign(static_cast<std::size_t>(frames), 0);
  r_.frame_particles.assign(static_cast<std::size_t>(frames), 0);

  // Events in the order their impacts land (frame, then file order); an impact after the last frame
  // of a shortened run lands in the last frame.
  std::vector<PendingEvent> events;
  for (const ImpactEvent& e : c_.impacts) {
    PendingEvent p;
    p.impact = &e.impact;
    p.impact_frame = std::min(e.frame, frames - 1);
    p.trigger_frame = schedule_ == ScheduleMode::prefetch ? std::max(0, p.impact_frame - c_.schedule.prefetch_frames)
                                                          : p.impact_frame;
    events.push_back(std::move(p));
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const PendingEvent& a, const PendingEvent& b) { return a.impact_frame < b.impact_frame; });
  for (std::size_t i = 0; i < events.size(); ++i) events[i].index = static_cast<int>(i);

  if (c_.debris.enabled) {
    debris_ = std::make_unique<DebrisField>(c_.debris, c_.gravity, bounding_box(solid_.mesh).min.z());
  } else {
    r_.stages.skipped(Stage::debris, "the case has no debris (case key debris)");
  }
  if (c_.fade_out.enabled && !world_)
    r_.stages.skipped(Stage::colliders, "fade-out: no physics world (case needs)");

  std::size_t next = 0;
  for (frame_ = 0; frame_ < frames; ++frame_) {
    instruction_marks::set_frame(frame_);
    const double cpu_start = thread_cpu_ms();
    const auto start = std::chrono::steady_clock::now();
    bool event_frame = false;
    for (const PendingEvent& e : events) event_frame = event_frame || e.impact_frame == frame_;
    while (next < events.size() && events[next].trigger_frame <= frame_) queue_.push_back(&events[next++]);
    if (Status s = event_work(frame_ == frames - 1); !s) return s.error();
    if (world_) fade_out();
    if (world_ && plan_.physics) {
      StageTimer timer(r_.frame_stages, Stage::physics);
#ifdef SHATTER_PLANTED_SLOWDOWN_SHARE
      const double step_start = thread_cpu_ms();
      world_->step();
      planted_work(thread_cpu_ms() - step_start, SHATTER_PLANTED_SLOWDOWN_SHARE);
#else
      world_->step();
#endif
    }
    if (debris_ && debris_->size() > 0) {
      StageTimer timer(r_.frame_stages, Stage::debris);
      debris_->step(1.0 / 60.0);
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const auto f = static_cast<std::size_t>(frame_);
    r_.frame_ms[f] = ms;
    r_.frame_cpu_ms[f] = thread_cpu_ms() - cpu_start;
    r_.frame_bodies[f] = world_ ? world_->body_count() : 0;
    r_.frame_particles[f] = debris_ ? debris_->size() : 0;
    r_.bodies_peak = std::max(r_.bodies_peak, r_.frame_bodies[f]);
    r_.particles_peak = std::max(r_.particles_peak, r_.frame_particles[f]);
    if (event_frame) {
      if (r_.event_frames.empty()) r_.event_ms = ms;
      r_.event_frames.push_back(frame_);
    }
  }
  if (world_ && plan_.physics) r_.stages.ran(Stage::physics);
  for (const PendingEvent& e : events) {
    EventLatency l;
    l.trigger_frame = e.trigger_frame;
    l.impact_frame = e.impact_frame;
    l.visible_frame = e.visible_frame;
    if (e.visible_frame >= 0) {
      l.frames = e.visible_frame - e.trigger_frame + 1;
      l.after_impact = e.visible_frame - e.impact_frame;
      l.ms = paced_ms(r_.frame_ms, e.trigger_frame, e.visible_frame);
    }
    r_.latencies.push_back(l);
    if (r_.latency.visible_frame < 0 || l.ms > r_.latency.ms) r_.latency = l;
  }
  measure_runtime_error(r_.hit, r_.pieces);  // after the frames: a measurement, not a stage
  if (world_) r_.bodies = world_->body_count();
  return std::move(r_);
}

}  // namespace

Result<PreparedCase> prepare_case(Case c) {
  Result<Solid> solid = build_case_solid(c);
  if (!solid) return solid.error();
  return PreparedCase{std::move(c), std::move(*solid)};
}

Result<RunResult> run_destruction(const PreparedCase& prepared, const RunOptions& options) {
  return Run(prepared, options).execute();
}

}  // namespace shatter
