#include "harness/pipeline/destruction_run.h"

#include "algorithms/bonds/graph_components.h"
#include "algorithms/fracture/local_fracture.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "algorithms/register_all.h"
#include "algorithms/stress/propagation.h"
#include "harness/cases/case_mesh.h"
#include "harness/pipeline/physics/physics_world.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
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
  Status event(int frame, const Impact& impact, int event_index);
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
  int runtime_fragments_ = 0;
  Loads loads_;

  std::vector<std::uint8_t> standing_;     // per fragment: still part of the held structure
  std::vector<std::uint8_t> anchored_;     // per fragment: overlaps an anchor region
  std::vector<int> static_body_;           // per fragment: its static body id, or -1
  std::unique_ptr<PhysicsWorld> world_;
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
  auto p = propagate(*model_, r_.graph, loads_, c_.material, broken, settings);
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

Status Run::event(int frame, const Impact& impact, int event_index) {
  StageClocks& t = r_.frame_stages;
  std::vector<int> hit;
  std::vector<std::vector<Fragment>> pieces;
  {
    StageTimer timer(t, Stage::runtime_fracture);
    NearImpactOptions near;
    near.eligible = standing_;
    near.cull_by_box = !o_.no_skip;
    hit = fragments_near_impact(r_.fragments, impact, near);
    FractureParams params;
    params.fragments = runtime_fragments_;
    params.impact = impact;
    for (std::size_t k = 0; k < hit.size(); ++k) {
      params.seed = r_.runtime_seed + 1000003ULL * static_cast<std::uint64_t>(event_index) + k;
      auto p = runtime_fracturer_->fracture(r_.fragments[static_cast<std::size_t>(hit[k])].mesh, params);
      if (!p) return Error{c_.name + ": runtime fracture at frame " + std::to_string(frame) + ": " + p.error().message};
      pieces.push_back(std::move(*p));
    }
  }
  if (hit.empty()) {
    r_.stages.skipped(Stage::runtime_fracture,
                      fmt::format("the impact at frame {} reaches no standing fragment (radius {} m): no runtime "
                                  "fracture, nothing after it",
                                  frame, impact.radius));
    return {};
  }
  r_.stages.ran(Stage::runtime_fracture);
  if (!o_.no_skip && impact.radius > 0) {
    const auto standing = std::count(standing_.begin(), standing_.end(), std::uint8_t{1});
    r_.stages.skipped(Stage::runtime_fracture,
                      fmt::format("{} of {} standing fragments outside the impact radius: not fractured, not copied",
                                  standing - static_cast<long>(hit.size()), standing));
  }
  if (plan_.bonds) {
    StageTimer timer(t, Stage::bond_update);
    for (const int f : hit)
      for (const int b : r_.graph.node_bonds[static_cast<std::size_t>(f)]) r_.broken[static_cast<std::size_t>(b)] = 1;
    r_.stages.ran(Stage::bond_update);
  } else {
    r_.stages.skipped(Stage::bond_update, "no bonds (case needs)");
  }
  for (const int f : hit) standing_[static_cast<std::size_t>(f)] = 0;

  std::vector<std::vector<int>> falling;
  if (plan_.bonds) {
    if (Status s = stress_after(hit, t); !s) return s;
    StageTimer timer(t, Stage::falling_clusters);
    falling = newly_falling();
    for (const std::vector<int>& cluster : falling)
      for (const int f : cluster) standing_[static_cast<std::size_t>(f)] = 0;
    r_.stages.ran(Stage::falling_clusters);
  }

  if (world_) {
    StageTimer timer(t, Stage::colliders);
    const double density = c_.material.density;
    for (const int f : hit) world_->remove(static_body_[static_cast<std::size_t>(f)]);
    double total_mass = 0.0;
    for (const auto& list : pieces)
      for (const Fragment& p : list) total_mass += density * p.mass.volume;
    const Vec3 velocity_change = total_mass > 0 ? Vec3(impact.direction * (impact.impulse / total_mass)) : Vec3::Zero();
    for (const auto& list : pieces) {
      for (const Fragment& p : list) {
        const int body = world_->add_fragment(p, density);
        const double mass = density * p.mass.volume;
        if (impact.impulse > 0) world_->apply_impulse(body, velocity_change * mass, p.mass.centroid);
      }
    }
    std::vector<Fragment> members;
    for (const std::vector<int>& cluster : falling) {
      members.clear();
      for (const int f : cluster) {
        world_->remove(static_body_[static_cast<std::size_t>(f)]);
        members.push_back(r_.fragments[static_cast<std::size_t>(f)]);
      }
      world_->add_cluster(members, density);
    }
  }
  for (std::size_t k = 0; k < hit.size(); ++k) {
    r_.hit.push_back(hit[k]);
    r_.pieces.push_back(std::move(pieces[k]));
  }
  for (std::vector<int>& cluster : falling) r_.falling_clusters.push_back(std::move(cluster));
  return {};
}

Result<RunResult> Run::execute() {
  plan_ = plan_for(c_.needs);
  instruction_marks::set_frame(-1);
  if (Status s = setup(); !s) return s.error();
  r_.runtime_seed = c_.prefracture.seed + o_.repetition;

  const int frames = o_.frames > 0 ? o_.frames : c_.frames;
  r_.frame_ms.assign(static_cast<std::size_t>(frames), 0.0);
  r_.frame_cpu_ms.assign(static_cast<std::size_t>(frames), 0.0);
  int event_index = 0;
  for (int frame = 0; frame < frames; ++frame) {
    instruction_marks::set_frame(frame);
    const double cpu_start = thread_cpu_ms();
    const auto start = std::chrono::steady_clock::now();
    bool event_frame = false;
    for (const ImpactEvent& e : c_.impacts) {
      // An impact after the last frame of a shortened run lands in the last frame.
      if (std::min(e.frame, frames - 1) != frame) continue;
      event_frame = true;
      if (Status s = event(frame, e.impact, event_index++); !s) return s.error();
    }
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
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    r_.frame_ms[static_cast<std::size_t>(frame)] = ms;
    r_.frame_cpu_ms[static_cast<std::size_t>(frame)] = thread_cpu_ms() - cpu_start;
    if (event_frame) {
      if (r_.event_frames.empty()) r_.event_ms = ms;
      r_.event_frames.push_back(frame);
    }
  }
  if (world_ && plan_.physics) r_.stages.ran(Stage::physics);
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
