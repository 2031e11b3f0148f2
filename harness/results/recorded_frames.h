#pragma once
/// A destruction run recorded for playback (`grid --record-frames`): every body's pose in every frame,
/// which bodies entered the world and which touched something in each frame, the frame's stage times,
/// and each body's meshes once, so that a viewer can draw the run frame by frame. The sidecar file
/// (`OUT.frames.bin` beside `--json OUT`) holds the recordings of a grid; docs/results.md ("Recorded
/// frames") gives its layout byte by byte.
///
/// Design note: a binary sidecar rather than base64 in the JSON. Poses are most of a recording (500
/// bodies over 300 frames are 150,000 of them) and base64 would add a third to them and put megabytes
/// into a file that `compare` and `merge` read whole; the sidecar is read only by what plays it back,
/// and a browser reads its planes as typed arrays (little-endian, each plane 4-byte aligned).
/// Quantised: a position is three float32 (1 mm in 16 km), a rotation the three smallest quaternion
/// components as int16 (the largest one restored from unit length; about 2e-5 rad), a mesh vertex
/// three uint16 over its mesh's box (1/65,535 of the piece's size), a scale one uint8: 20 bytes a
/// pose. In memory everything is decoded to float: the reader gives what the viewer draws.

#include "algorithms/core/result.h"
#include "harness/results/frame_stage_times.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace shatter {

/// Version of the sidecar's layout (after its 8-byte magic `SBFRAMES`); raised on any change of it.
inline constexpr std::uint32_t kRecordedFramesVersion = 1;

/// What a recorded body is.
enum class RecordedBodyKind : std::uint8_t {
  fragment = 0,  ///< one pre-fracture fragment: standing (static) or loose from the start (dynamic)
  piece = 1,     ///< one runtime piece of a hit fragment (dynamic)
  cluster = 2,   ///< a falling cluster of pre-fracture fragments, one compound body (dynamic)
};

/// One mesh of a recording, in the run's world coordinates at rest (where the fragment was made).
struct RecordedMesh {
  int fragment = -1;  ///< the pre-fracture fragment it is, or the hit fragment it is a piece of
  int piece = -1;     ///< its index among that hit fragment's pieces; -1 for a pre-fracture fragment
  std::vector<std::array<float, 3>> vertices;          ///< m, #V
  std::vector<std::array<std::uint32_t, 3>> triangles; ///< #T, indices into vertices, counter-clockwise from outside
};

/// One body of a recording.
struct RecordedBody {
  RecordedBodyKind kind = RecordedBodyKind::fragment;  ///< what it is
  int fragment = -1;  ///< fragment: its pre-fracture index; piece: its hit fragment's; cluster: -1
  int piece = -1;     ///< piece: its index among its hit fragment's pieces; else -1
  std::vector<std::uint32_t> meshes;  ///< indices into RecordedFrames::meshes: one, or a cluster's members
  /// Its centroid at rest, m: a mesh vertex x is drawn at `rotation * (x - rest_centroid) + position`.
  std::array<float, 3> rest_centroid{};
};

/// BodyPose::flags: the body is in the world at the end of the frame.
inline constexpr std::uint8_t kPosePresent = 1;
/// BodyPose::flags: the body entered the world in this frame.
inline constexpr std::uint8_t kPoseSpawned = 2;
/// BodyPose::flags: the body has contact points with another body (Bullet's contact manifolds).
inline constexpr std::uint8_t kPoseTouchingBody = 4;
/// BodyPose::flags: the body has contact points with the ground.
inline constexpr std::uint8_t kPoseTouchingGround = 8;

/// Where one body is at the end of one frame. A body not in the world has its rest pose before it
/// enters and its last pose after it leaves, with no flag set.
struct BodyPose {
  std::array<float, 3> position{};            ///< its centroid, m, world
  std::array<float, 4> rotation{0, 0, 0, 1};  ///< unit quaternion (x, y, z, w): mesh coordinates to world
  float scale = 1.0f;                         ///< its collider's scale (a fading piece shrinks to 0), 1 as made
  std::uint8_t flags = 0;                     ///< kPosePresent, kPoseSpawned, kPoseTouchingBody, kPoseTouchingGround
};

/// One recorded run: a repetition of one grid cell.
struct RecordedFrames {
  int prefracture = 0;                 ///< the cell's requested pre-fracture count
  int runtime = 0;                     ///< the cell's requested runtime count
  int repetition = 0;                  ///< which repetition of the cell was recorded
  std::uint64_t seed = 0;              ///< its pre-fracture seed
  int frames = 0;                      ///< frames of the run
  std::vector<double> frame_ms;        ///< wall time of each frame, ms, #frames
  FrameStageTimes stage_ms;            ///< each stage's wall time in each frame, ms (as the results' frame_stages_ms)
  std::vector<RecordedMesh> meshes;    ///< every mesh a body is drawn with, once
  std::vector<RecordedBody> bodies;    ///< every body that was in the world in some frame, in order of entry
  std::vector<BodyPose> poses;         ///< #frames x #bodies, frame-major: pose(f, b) = poses[f * #bodies + b]

  /// The pose of body `body` at the end of frame `frame`.
  [[nodiscard]] const BodyPose& pose(int frame, int body) const {
    return poses[static_cast<std::size_t>(frame) * bodies.size() + static_cast<std::size_t>(body)];
  }
};

/// The sidecar of results JSON `json`: `OUT.frames.bin` for `OUT.json` (the extension replaced).
[[nodiscard]] std::filesystem::path recorded_frames_beside(const std::filesystem::path& json);

/// The sidecar's bytes for `recordings` (docs/results.md, "Recorded frames"). Each recording must be
/// whole: frame_ms of #frames values, stage columns empty or #frames long, poses #frames x #bodies,
/// mesh indices in range (programmer errors otherwise: asserts).
[[nodiscard]] std::string encode_recorded_frames(std::span<const RecordedFrames> recordings);

/// The recordings of sidecar bytes `bytes`; an error naming `what` and the part that is wrong for
/// anything that is not a whole, valid sidecar (every count checked against the bytes left before it
/// is allocated, every index in range, every number finite).
[[nodiscard]] Result<std::vector<RecordedFrames>> decode_recorded_frames(const std::string& bytes,
                                                                         const std::string& what);

/// Reads the sidecar at `path` (at most kMaxResultsFileBytes); errors name the file.
[[nodiscard]] Result<std::vector<RecordedFrames>> read_recorded_frames(const std::filesystem::path& path);

}  // namespace shatter
