#include "harness/pipeline/frame/frame_recorder.h"

#include "harness/pipeline/destruction_run.h"
#include "harness/pipeline/physics/physics_world.h"

#include <Eigen/Geometry>
#include <fmt/core.h>

#include <algorithm>
#include <cassert>
#include <map>
#include <utility>

namespace shatter {
namespace {

std::array<float, 3> to_float(const Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

BodyPose pose_of(const PhysicsWorld& world, int id) {
  BodyPose p;
  p.position = to_float(world.position(id));
  const Eigen::Quaterniond q = Eigen::Quaterniond(world.rotation(id)).normalized();
  p.rotation = {static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z()),
                static_cast<float>(q.w())};
  p.scale = static_cast<float>(world.scale(id));
  p.flags = kPosePresent;
  return p;
}

RecordedMesh recorded_mesh(const Mesh& mesh, int fragment, int piece) {
  RecordedMesh m;
  m.fragment = fragment;
  m.piece = piece;
  m.vertices.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) m.vertices.push_back(to_float(v));
  m.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    m.triangles.push_back({static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]),
                           static_cast<std::uint32_t>(t[2])});
  return m;
}

/// The meshes of a recording, each fragment and piece once.
class MeshTable {
 public:
  explicit MeshTable(const RunResult& run) : run_(run) {}

  /// The index of pre-fracture fragment `f`'s mesh (piece -1) or of piece `piece` of hit fragment
  /// `f`; -1 when the run has no such piece.
  int index(int f, int piece) {
    const auto [it, added] = index_.try_emplace({f, piece}, static_cast<int>(meshes_.size()));
    if (!added) return it->second;
    const Fragment* source = nullptr;
    if (piece < 0) {
      source = &run_.fragments.at(static_cast<std::size_t>(f));
    } else {
      const auto hit = std::find(run_.hit.begin(), run_.hit.end(), f);
      const std::size_t k = static_cast<std::size_t>(hit - run_.hit.begin());
      if (hit != run_.hit.end() && static_cast<std::size_t>(piece) < run_.pieces[k].size())
        source = &run_.pieces[k][static_cast<std::size_t>(piece)];
    }
    if (source == nullptr) {
      index_.erase(it);
      return -1;
    }
    meshes_.push_back(recorded_mesh(source->mesh, f, piece));
    return it->second;
  }
  std::vector<RecordedMesh> take() { return std::move(meshes_); }

 private:
  const RunResult& run_;
  std::map<std::pair<int, int>, int> index_;
  std::vector<RecordedMesh> meshes_;
};

}  // namespace

FrameRecorder::FrameRecorder(int frames, std::int64_t max_poses)
    : frames_(frames), max_poses_(max_poses), seen_(static_cast<std::size_t>(std::max(frames, 0))) {
  assert(frames >= 1);
}

void FrameRecorder::body_made(int id, BodyOrigin origin) {
  assert(id >= 0);
  if (static_cast<std::size_t>(id) >= origins_.size()) origins_.resize(static_cast<std::size_t>(id) + 1);
  origins_[static_cast<std::size_t>(id)] = std::move(origin);
}

std::int64_t FrameRecorder::poses() const { return static_cast<std::int64_t>(id_of_.size()) * frames_; }

Status FrameRecorder::record(const PhysicsWorld* world, int frame) {
  assert(frame >= 0 && frame < frames_);
  if (world == nullptr) return {};
  std::vector<Seen>& now = seen_[static_cast<std::size_t>(frame)];
  index_of_.resize(static_cast<std::size_t>(world->id_bound()), -1);
  std::vector<int> at(index_of_.size(), -1);  // by world id: its entry in `now`
  for (int id = 0; id < world->id_bound(); ++id) {
    if (!world->contains(id) || !world->in_world(id)) continue;
    int& index = index_of_[static_cast<std::size_t>(id)];
    BodyPose pose = pose_of(*world, id);
    if (index < 0) {
      index = static_cast<int>(id_of_.size());
      id_of_.push_back(id);
      rest_.push_back(to_float(world->mesh_centroid(id)));
      pose.flags |= kPoseSpawned;
    }
    at[static_cast<std::size_t>(id)] = static_cast<int>(now.size());
    now.push_back({index, pose});
  }
  for (const TouchingPair& pair : world->touching_pairs()) {
    const auto mark = [&](int id, std::uint8_t flag) {
      if (id < 0) return;  // the ground
      if (const int entry = at[static_cast<std::size_t>(id)]; entry >= 0)
        now[static_cast<std::size_t>(entry)].pose.flags |= flag;
    };
    mark(pair.first, pair.second < 0 ? kPoseTouchingGround : kPoseTouchingBody);
    mark(pair.second, pair.first < 0 ? kPoseTouchingGround : kPoseTouchingBody);
  }
  if (poses() > max_poses_) {
    over_limit_ = true;
    return Error{fmt::format("{} bodies x {} frames = {} poses exceed the limit of {}", id_of_.size(), frames_,
                             poses(), max_poses_)};
  }
  return {};
}

RecordedFrames FrameRecorder::finish(const RunResult& run) const {
  RecordedFrames out;
  out.frames = frames_;
  out.frame_ms = run.frame_ms;
  out.frame_ms.resize(static_cast<std::size_t>(frames_), 0.0);
  out.stage_ms = run.frame_stage_ms;
  MeshTable meshes(run);
  for (std::size_t index = 0; index < id_of_.size(); ++index) {
    const auto id = static_cast<std::size_t>(id_of_[index]);
    const BodyOrigin origin = id < origins_.size() ? origins_[id] : BodyOrigin{};
    RecordedBody body;
    body.kind = origin.kind;
    body.fragment = origin.kind == RecordedBodyKind::cluster ? -1 : origin.fragment;
    body.piece = origin.kind == RecordedBodyKind::piece ? origin.piece : -1;
    body.rest_centroid = rest_[index];
    const auto add = [&](int f, int piece) {
      if (f < 0) return;
      if (const int m = meshes.index(f, piece); m >= 0) body.meshes.push_back(static_cast<std::uint32_t>(m));
    };
    if (origin.kind == RecordedBodyKind::cluster) {
      for (const int f : origin.members) add(f, -1);
    } else {
      add(origin.fragment, origin.kind == RecordedBodyKind::piece ? origin.piece : -1);
    }
    out.bodies.push_back(std::move(body));
  }
  out.meshes = meshes.take();
  // Dense poses: a body's rest pose before it entered, its last pose (no flags) after it left.
  const std::size_t bodies = out.bodies.size();
  out.poses.resize(static_cast<std::size_t>(frames_) * bodies);
  std::vector<BodyPose> last(bodies);
  for (std::size_t b = 0; b < bodies; ++b) last[b].position = rest_[b];
  for (std::size_t f = 0; f < static_cast<std::size_t>(frames_); ++f) {
    BodyPose* row = &out.poses[f * bodies];
    for (std::size_t b = 0; b < bodies; ++b) {
      row[b] = last[b];
      row[b].flags = 0;
    }
    for (const Seen& s : seen_[f]) {
      row[static_cast<std::size_t>(s.body)] = s.pose;
      last[static_cast<std::size_t>(s.body)] = s.pose;
    }
  }
  return out;
}

}  // namespace shatter
