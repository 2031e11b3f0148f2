// Recording a run (grid --record-frames) in process: every body the run made is recorded with the
// meshes it is made of, in every frame; the first frame has the standing fragments where they were
// made; the bodies in the world at the end are the run's `bodies`; flags follow the world (entry,
// removal by the fade-out, contacts); the limit stops the run; recording changes no outcome.

#include "harness/limits.h"
#include "harness/pipeline/destruction_run.h"
#include "harness/pipeline/frame/frame_recorder.h"
#include "tests/support/builtin_registries.h"
#include "tests/support/prepared_case.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace {

using namespace shatter;

using test::prepared;

constexpr int kFrames = 40;

RunOptions options(ScheduleMode mode) {
  RunOptions o;
  o.partition_samples = 0;
  o.frames = kFrames;
  o.prefracture_fragments = 30;
  o.runtime_fragments = 10;
  o.schedule = mode;
  return o;
}

RunResult run(const PreparedCase& p, const RunOptions& o) {
  Result<RunResult> r = run_destruction(p, o, test::builtin_registries());
  INFO((r ? std::string() : r.error().message));
  REQUIRE(r);
  return std::move(*r);
}

std::array<float, 3> as_float(const Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

/// Equal to float precision (the world combines a fragment's centroid as sum V c / sum V).
bool near(const std::array<float, 3>& a, const Vec3& b) {
  for (int i = 0; i < 3; ++i)
    if (std::abs(a[i] - b[i]) > 1e-6 * (1.0 + std::abs(b[i]))) return false;
  return true;
}

}  // namespace

TEST_CASE("frame recorder: every body in every frame, with its meshes, entry, removal and contacts",
          "[pipeline][record-frames]") {
  PreparedCase p = prepared("building");
  p.spec.fade_out.enabled = true;
  p.spec.fade_out.max_volume = 1.0;  // every piece fades
  p.spec.fade_out.lifetime_frames = 8;
  for (const ScheduleMode mode : {ScheduleMode::immediate, ScheduleMode::amortized}) {
    INFO(schedule_mode_name(mode));
    FrameRecorder recorder(kFrames, kMaxRecordedPoses);
    RunOptions o = options(mode);
    o.recorder = &recorder;
    const RunResult r = run(p, o);
    const RecordedFrames rec = recorder.finish(r);
    REQUIRE(rec.frames == kFrames);
    REQUIRE(rec.frame_ms == r.frame_ms);
    REQUIRE(rec.stage_ms == r.frame_stage_ms);
    const std::size_t bodies = rec.bodies.size();
    REQUIRE(rec.poses.size() == bodies * kFrames);
    REQUIRE(recorder.poses() == static_cast<std::int64_t>(bodies) * kFrames);

    // What each body is: standing fragments, then the pieces of the hit fragments.
    std::size_t pieces = 0;
    for (const auto& list : r.pieces) pieces += list.size();
    REQUIRE(r.falling_clusters.empty());  // this impact drops nothing: fragments and pieces only
    REQUIRE(bodies == r.fragments.size() + pieces);
    for (const RecordedBody& b : rec.bodies) {
      REQUIRE(b.meshes.size() == 1);
      const RecordedMesh& m = rec.meshes[b.meshes[0]];
      REQUIRE(m.fragment == b.fragment);
      REQUIRE(m.piece == b.piece);
      const Fragment& source =
          b.kind == RecordedBodyKind::piece
              ? r.pieces[static_cast<std::size_t>(std::find(r.hit.begin(), r.hit.end(), b.fragment) - r.hit.begin())]
                        [static_cast<std::size_t>(b.piece)]
              : r.fragments[static_cast<std::size_t>(b.fragment)];
      REQUIRE(m.vertices.size() == source.mesh.vertices.size());
      REQUIRE(m.vertices[0] == as_float(source.mesh.vertices[0]));
      REQUIRE(m.triangles.size() == source.mesh.triangles.size());
      REQUIRE(near(b.rest_centroid, source.mass.centroid));
    }

    // The first frame: every standing fragment where it was made, unturned.
    int present_first = 0;
    for (std::size_t b = 0; b < bodies; ++b) {
      const BodyPose& pose = rec.pose(0, static_cast<int>(b));
      if (!(pose.flags & kPosePresent)) continue;
      ++present_first;
      REQUIRE(rec.bodies[b].kind == RecordedBodyKind::fragment);
      REQUIRE((pose.flags & kPoseSpawned));
      REQUIRE(pose.position == rec.bodies[b].rest_centroid);
      REQUIRE(std::abs(pose.rotation[3]) > 1.0f - 1e-6f);  // unturned, to Bullet's float basis
    }
    REQUIRE(present_first == static_cast<int>(r.fragments.size()));

    // Entry once, at the first frame present; flags only while present; the end is the run's bodies.
    bool touched = false, shrank = false;
    for (std::size_t b = 0; b < bodies; ++b) {
      int entries = 0, first = -1, last = -1;
      for (int f = 0; f < kFrames; ++f) {
        const BodyPose& pose = rec.pose(f, static_cast<int>(b));
        if (pose.flags & kPoseSpawned) ++entries;
        if (!(pose.flags & kPosePresent)) {
          REQUIRE(pose.flags == 0);
          continue;
        }
        if (first < 0) first = f;
        REQUIRE((last < 0 || last == f - 1));  // no body comes back
        last = f;
        touched = touched || (pose.flags & (kPoseTouchingBody | kPoseTouchingGround)) != 0;
        shrank = shrank || pose.scale < 1.0f;
      }
      REQUIRE(entries == 1);
      REQUIRE((rec.pose(first, static_cast<int>(b)).flags & kPoseSpawned));
    }
    REQUIRE(touched);
    REQUIRE(shrank);
    int present_last = 0;
    for (std::size_t b = 0; b < bodies; ++b)
      present_last += (rec.pose(kFrames - 1, static_cast<int>(b)).flags & kPosePresent) ? 1 : 0;
    REQUIRE(present_last == r.bodies);
    REQUIRE(r.faded > 0);
  }
}

TEST_CASE("frame recorder: recording changes no outcome, and its limit stops the run", "[pipeline][record-frames]") {
  const PreparedCase p = prepared("building");
  const RunResult plain = run(p, options(ScheduleMode::immediate));
  FrameRecorder recorder(kFrames, kMaxRecordedPoses);
  RunOptions o = options(ScheduleMode::immediate);
  o.recorder = &recorder;
  const RunResult recorded = run(p, o);
  REQUIRE(recorded.hit == plain.hit);
  REQUIRE(recorded.broken == plain.broken);
  REQUIRE(recorded.frame_bodies == plain.frame_bodies);
  REQUIRE(recorded.bodies == plain.bodies);

  FrameRecorder small(kFrames, 10 * kFrames);  // room for 10 bodies, the first frame has 30 or more
  o.recorder = &small;
  const Result<RunResult> stopped = run_destruction(p, o, test::builtin_registries());
  REQUIRE_FALSE(stopped);
  REQUIRE(small.over_limit());
  REQUIRE(stopped.error().message.find("exceed the limit of 400") != std::string::npos);
}
