#pragma once
/// Debris and dust of the runtime events: point particles spawned per event (a count per m^2 of new
/// cut area plus a count per impact), integrated every frame under gravity against the ground plane,
/// removed at the end of their life (the seed's smoke and debris, docs/pipeline.md section 6).
///
/// Design note: particles do not collide with bodies or each other (dust is visual; what it costs is
/// the spawn and the per-frame integration, which is what the `debris` stage times). Plain arrays of
/// position, velocity and age, one entry per particle, removed by swap-with-last. Directions come from
/// a seeded generator, so a run is deterministic.

#include "algorithms/core/mesh.h"
#include "harness/cases/case.h"

#include <cstdint>
#include <random>
#include <vector>

namespace shatter {

/// The live particles of a run.
class DebrisField {
 public:
  /// A field for `spec`, with `gravity` (m/s^2) and a ground plane at z = `ground_z` (m).
  DebrisField(const DebrisSpec& spec, const Vec3& gravity, double ground_z);

  /// Particles one event spawns: round(per_area * cut_area_m2) + per_impact, at most kMaxDebrisPerEvent.
  [[nodiscard]] int count_for(double cut_area_m2) const;
  /// Spawns `count` particles at `origins` (taken round robin; non-empty), each with the case's speed in
  /// a direction drawn from `seed` (the upper hemisphere about +z), no more than keep the field within
  /// kMaxDebrisParticles. Returns the count spawned.
  int spawn(int count, const std::vector<Vec3>& origins, std::uint64_t seed);
  /// One frame of `dt` s: every particle ages by one frame and moves (semi-implicit Euler; at the
  /// ground it stops falling and slides with friction); a particle that has lived lifetime_frames
  /// frames is removed at the end of this one.
  void step(double dt);
  /// Particles alive.
  [[nodiscard]] int size() const { return static_cast<int>(position_.size()); }

 private:
  DebrisSpec spec_;
  Vec3 gravity_;
  double ground_z_;
  std::vector<Vec3> position_;
  std::vector<Vec3> velocity_;
  std::vector<int> age_;  // frames lived
};

/// New cut area of one hit fragment: (sum of its pieces' surface areas - its own) / 2, m^2 (each new
/// face is shared by two pieces).
double new_cut_area(const Fragment& parent, const std::vector<Fragment>& pieces);

}  // namespace shatter
