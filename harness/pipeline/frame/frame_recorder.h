#pragma once
/// Recording a run for playback (`grid --record-frames`): after each frame, outside its time, every
/// body's pose, whether it entered the world in that frame and whether it touches another body or the
/// ground; at the end, the recording (harness/results/recorded_frames.h) with each body's meshes.
///
/// Design note: the pipeline tells the recorder what each body is made of where it makes the body
/// (body_made: the setup's fragments and clusters, the event's pieces and clusters), because a body
/// id says nothing about its fragments; the meshes are taken from the run's result at the end, where
/// every fragment and piece is, so nothing is copied while frames are timed. The recorder is the
/// caller's (RunOptions::recorder), as the pre-fracture cache is: the caller sets its limit and, when
/// a run fails, asks whether the limit was the reason (over_limit).

#include "algorithms/core/result.h"
#include "harness/results/recorded_frames.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shatter {

class PhysicsWorld;
struct RunResult;

/// What a body of the physics world is made of.
struct BodyOrigin {
  RecordedBodyKind kind = RecordedBodyKind::fragment;  ///< what it is
  int fragment = -1;         ///< fragment: its pre-fracture index; piece: its hit fragment's
  int piece = -1;            ///< piece: its index among its hit fragment's pieces
  std::vector<int> members;  ///< cluster: its pre-fracture fragments
};

/// Records the bodies of one run frame by frame.
class FrameRecorder {
 public:
  /// A recorder of a run of `frames` frames (>= 1) that may hold at most `max_poses` poses (bodies
  /// seen x frames; kMaxRecordedPoses less what a grid recorded before).
  FrameRecorder(int frames, std::int64_t max_poses);

  /// Notes that the run made body `id` of its physics world from `origin`.
  void body_made(int id, BodyOrigin origin);

  /// Records every body of `world` (none when null) at the end of frame `frame` (frames in order, each
  /// once). An error, and over_limit() true, when the bodies seen so far times the run's frames
  /// exceed the limit: "B bodies x F frames = P poses exceed the limit of L".
  Status record(const PhysicsWorld* world, int frame);

  /// True when record() refused a frame for the limit.
  [[nodiscard]] bool over_limit() const { return over_limit_; }

  /// Poses the recording holds: bodies seen so far x the run's frames.
  [[nodiscard]] std::int64_t poses() const;

  /// The recording of `run` (the run this recorder recorded, after its last frame): its frame and
  /// stage times, every body seen with its meshes (from the run's fragments and pieces) and its pose in
  /// every frame. The cell, repetition and seed are left for the caller.
  [[nodiscard]] RecordedFrames finish(const RunResult& run) const;

 private:
  /// One body seen in one frame.
  struct Seen {
    int body = 0;   ///< index in order of entry
    BodyPose pose;  ///< its pose and flags
  };

  int frames_;
  std::int64_t max_poses_;
  bool over_limit_ = false;
  std::vector<BodyOrigin> origins_;     ///< by world id
  std::vector<int> index_of_;           ///< by world id: index in order of entry, or -1
  std::vector<std::array<float, 3>> rest_;  ///< by index: its centroid at rest
  std::vector<int> id_of_;              ///< by index: its world id
  std::vector<std::vector<Seen>> seen_; ///< by frame: the bodies in the world
};

}  // namespace shatter
