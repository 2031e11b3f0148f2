#include "harness/results/recorded_frames.h"

#include "algorithms/assets/mesh_codec.h"
#include "algorithms/core/bounded_read.h"
#include "harness/limits.h"

#include <fmt/core.h>

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <limits>

namespace shatter {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the sidecar is little-endian: written and read in the machine's order");

constexpr char kMagic[8] = {'S', 'B', 'F', 'R', 'A', 'M', 'E', 'S'};
constexpr std::uint32_t kVersion = kRecordedFramesVersion;
/// Flags bits 4-5: which quaternion component was dropped (the largest); bits 6-7 are 0.
constexpr unsigned kDroppedShift = 4;
constexpr std::uint8_t kPoseFlagBits = kPosePresent | kPoseSpawned | kPoseTouchingBody | kPoseTouchingGround;
constexpr double kRotationScale = 32767.0 * 1.4142135623730951;  // a smallest component is <= 1/sqrt(2)
constexpr double kMeshSteps = 65535.0;
/// Vertices a mesh may have for 16-bit triangle indices.
constexpr std::uint32_t kShortIndexVertices = 65536;

void pad(BinaryWriter& w, std::size_t alignment) {
  static constexpr char zeros[8] = {};
  w.bytes(zeros, (alignment - w.data().size() % alignment) % alignment);
}

/// The three smallest components of unit quaternion `q`, the largest made positive, and its index.
std::array<std::int16_t, 3> smallest_three(const std::array<float, 4>& q, unsigned& dropped) {
  dropped = 0;
  for (unsigned i = 1; i < 4; ++i)
    if (std::abs(q[i]) > std::abs(q[dropped])) dropped = i;
  const double sign = q[dropped] < 0.0f ? -1.0 : 1.0;
  std::array<std::int16_t, 3> out{};
  unsigned k = 0;
  for (unsigned i = 0; i < 4; ++i)
    if (i != dropped)
      out[k++] = static_cast<std::int16_t>(std::lround(std::clamp(sign * q[i] * kRotationScale, -32767.0, 32767.0)));
  return out;
}

std::array<float, 4> from_smallest_three(const std::array<std::int16_t, 3>& s, unsigned dropped) {
  std::array<double, 4> q{};
  double sum = 0.0;
  unsigned k = 0;
  for (unsigned i = 0; i < 4; ++i) {
    if (i == dropped) continue;
    q[i] = s[k++] / kRotationScale;
    sum += q[i] * q[i];
  }
  q[dropped] = std::sqrt(std::max(0.0, 1.0 - sum));
  const double norm = std::sqrt(sum + q[dropped] * q[dropped]);
  return {static_cast<float>(q[0] / norm), static_cast<float>(q[1] / norm), static_cast<float>(q[2] / norm),
          static_cast<float>(q[3] / norm)};
}

void write_mesh_entry(BinaryWriter& w, const RecordedMesh& m) {
  std::array<float, 3> lo{}, hi{};
  for (int a = 0; a < 3; ++a) {
    lo[a] = m.vertices.empty() ? 0.0f : std::numeric_limits<float>::max();
    hi[a] = m.vertices.empty() ? 0.0f : std::numeric_limits<float>::lowest();
  }
  for (const auto& v : m.vertices)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], v[a]);
      hi[a] = std::max(hi[a], v[a]);
    }
  std::array<float, 3> step{};
  for (int a = 0; a < 3; ++a) step[a] = static_cast<float>((static_cast<double>(hi[a]) - lo[a]) / kMeshSteps);
  w.value(static_cast<std::int32_t>(m.fragment));
  w.value(static_cast<std::int32_t>(m.piece));
  w.value(static_cast<std::uint32_t>(m.vertices.size()));
  w.value(static_cast<std::uint32_t>(m.triangles.size()));
  w.value(lo);
  w.value(step);
  for (const auto& v : m.vertices)
    for (int a = 0; a < 3; ++a) {
      const double q = step[a] > 0.0f ? (static_cast<double>(v[a]) - lo[a]) / step[a] : 0.0;
      w.value(static_cast<std::uint16_t>(std::lround(std::clamp(q, 0.0, kMeshSteps))));
    }
  pad(w, 4);
  const bool short_indices = m.vertices.size() <= kShortIndexVertices;
  for (const auto& t : m.triangles)
    for (const std::uint32_t i : t) {
      assert(i < m.vertices.size());
      if (short_indices) w.value(static_cast<std::uint16_t>(i));
      else w.value(i);
    }
  pad(w, 4);
}

void write_body_entry(BinaryWriter& w, const RecordedBody& b, std::size_t meshes) {
  const std::uint8_t head[4] = {static_cast<std::uint8_t>(b.kind), 0, 0, 0};
  w.bytes(head, sizeof head);
  w.value(static_cast<std::int32_t>(b.fragment));
  w.value(static_cast<std::int32_t>(b.piece));
  w.value(b.rest_centroid);
  w.value(static_cast<std::uint32_t>(b.meshes.size()));
  for (const std::uint32_t m : b.meshes) {
    assert(m < meshes);
    (void)meshes;
    w.value(m);
  }
}

/// One recording's block; its length is a multiple of 8.
std::string recording_block(const RecordedFrames& r) {
  const auto frames = static_cast<std::size_t>(r.frames);
  assert(r.frame_ms.size() == frames && r.poses.size() == frames * r.bodies.size());
  BinaryWriter w;
  w.value(static_cast<std::int32_t>(r.prefracture));
  w.value(static_cast<std::int32_t>(r.runtime));
  w.value(static_cast<std::int32_t>(r.repetition));
  w.value(static_cast<std::uint32_t>(r.frames));
  w.value(r.seed);
  std::uint32_t stage_mask = 0;
  for (std::size_t s = 0; s < kStageCount; ++s) {
    assert(r.stage_ms[s].empty() || r.stage_ms[s].size() == frames);
    if (!r.stage_ms[s].empty()) stage_mask |= 1u << s;
  }
  w.value(static_cast<std::uint32_t>(r.meshes.size()));
  w.value(static_cast<std::uint32_t>(r.bodies.size()));
  w.value(stage_mask);
  w.value(std::uint32_t{0});
  w.bytes(r.frame_ms.data(), frames * sizeof(double));
  for (const std::vector<double>& column : r.stage_ms) w.bytes(column.data(), column.size() * sizeof(double));
  for (const RecordedMesh& m : r.meshes) write_mesh_entry(w, m);
  for (const RecordedBody& b : r.bodies) write_body_entry(w, b, r.meshes.size());
  pad(w, 4);
  for (const BodyPose& p : r.poses) w.value(p.position);
  std::vector<std::uint8_t> flags;
  flags.reserve(r.poses.size());
  for (const BodyPose& p : r.poses) {
    unsigned dropped = 0;
    w.value(smallest_three(p.rotation, dropped));
    flags.push_back(static_cast<std::uint8_t>((p.flags & kPoseFlagBits) | (dropped << kDroppedShift)));
  }
  pad(w, 4);
  w.bytes(flags.data(), flags.size());
  for (const BodyPose& p : r.poses)
    w.value(static_cast<std::uint8_t>(std::lround(std::clamp(static_cast<double>(p.scale), 0.0, 1.0) * 255.0)));
  pad(w, 8);
  return w.data();
}


/// Reads one sidecar, tracking where it is; every read is bounds-checked (BinaryReader).
class SidecarReader {
 public:
  explicit SidecarReader(const std::string& bytes) : bytes_(bytes), in_(bytes) {}
  template <class T>
  T value() { return in_.value<T>(); }
  void bytes(void* p, std::size_t n) { in_.bytes(p, n); }
  /// True when `count` items of `size` bytes can still be read (checked before allocating them).
  [[nodiscard]] bool fits(std::uint64_t count, std::uint64_t size) const {
    return in_.ok() && (size == 0 || count <= in_.left() / size);
  }
  [[nodiscard]] std::size_t position() const { return bytes_.size() - in_.left(); }
  /// Skips the padding to `alignment`; false when it is not zeros or runs past the end.
  bool padding(std::size_t alignment) {
    char zeros[8] = {};
    const std::size_t n = (alignment - position() % alignment) % alignment;
    in_.bytes(zeros, n);
    return in_.ok() && std::all_of(zeros, zeros + n, [](char c) { return c == 0; });
  }
  [[nodiscard]] bool ok() const { return in_.ok(); }
  [[nodiscard]] bool at_end() const { return in_.at_end(); }

 private:
  const std::string& bytes_;
  BinaryReader in_;
};

/// A failed check of the part named.
struct Bad {
  std::string part;
};

bool finite3(const std::array<float, 3>& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

void require(bool ok, const char* part) {
  if (!ok) throw Bad{part};
}

RecordedMesh read_mesh_entry(SidecarReader& in) {
  RecordedMesh m;
  m.fragment = in.value<std::int32_t>();
  m.piece = in.value<std::int32_t>();
  const auto vertices = in.value<std::uint32_t>();
  const auto triangles = in.value<std::uint32_t>();
  const auto lo = in.value<std::array<float, 3>>();
  const auto step = in.value<std::array<float, 3>>();
  require(in.ok() && m.fragment >= 0 && m.piece >= -1, "mesh header");
  require(finite3(lo) && finite3(step) && step[0] >= 0 && step[1] >= 0 && step[2] >= 0, "mesh box");
  require(in.fits(vertices, 6), "mesh vertices");
  m.vertices.resize(vertices);
  for (auto& v : m.vertices)
    for (int a = 0; a < 3; ++a) v[a] = lo[a] + static_cast<float>(in.value<std::uint16_t>()) * step[a];
  require(in.padding(4), "mesh vertices");
  const bool short_indices = vertices <= kShortIndexVertices;
  require(in.fits(triangles, short_indices ? 6 : 12), "mesh triangles");
  m.triangles.resize(triangles);
  for (auto& t : m.triangles)
    for (std::uint32_t& i : t) {
      i = short_indices ? in.value<std::uint16_t>() : in.value<std::uint32_t>();
      require(i < vertices, "mesh triangles: an index out of range");
    }
  require(in.padding(4), "mesh triangles");
  return m;
}

RecordedBody read_body_entry(SidecarReader& in, std::size_t meshes) {
  RecordedBody b;
  std::uint8_t head[4] = {};
  in.bytes(head, sizeof head);
  require(in.ok() && head[0] <= static_cast<std::uint8_t>(RecordedBodyKind::cluster), "body kind");
  require(head[1] == 0 && head[2] == 0 && head[3] == 0, "body header");
  b.kind = static_cast<RecordedBodyKind>(head[0]);
  b.fragment = in.value<std::int32_t>();
  b.piece = in.value<std::int32_t>();
  b.rest_centroid = in.value<std::array<float, 3>>();
  require(in.ok() && finite3(b.rest_centroid) && b.fragment >= -1 && b.piece >= -1, "body");
  const auto count = in.value<std::uint32_t>();
  require(in.fits(count, 4), "body meshes");
  b.meshes.resize(count);
  for (std::uint32_t& m : b.meshes) {
    m = in.value<std::uint32_t>();
    require(m < meshes, "body meshes: an index out of range");
  }
  return b;
}

void read_poses(SidecarReader& in, RecordedFrames& r) {
  const std::size_t n = r.poses.size();
  for (BodyPose& p : r.poses) {
    p.position = in.value<std::array<float, 3>>();
    require(finite3(p.position), "pose positions");
  }
  std::vector<std::array<std::int16_t, 3>> rotations(n);
  for (auto& q : rotations) q = in.value<std::array<std::int16_t, 3>>();
  require(in.padding(4), "pose rotations");
  for (std::size_t i = 0; i < n; ++i) {
    const auto flags = in.value<std::uint8_t>();
    require(flags >> (kDroppedShift + 2) == 0, "pose flags");
    r.poses[i].flags = flags & kPoseFlagBits;
    r.poses[i].rotation = from_smallest_three(rotations[i], (flags >> kDroppedShift) & 3u);
  }
  for (BodyPose& p : r.poses) p.scale = static_cast<float>(in.value<std::uint8_t>() / 255.0);
  require(in.padding(8), "pose scales");
}

std::vector<double> read_times(SidecarReader& in, std::size_t frames, const char* part) {
  std::vector<double> out(frames);
  in.bytes(out.data(), frames * sizeof(double));
  for (const double ms : out) require(in.ok() && std::isfinite(ms) && ms >= 0.0, part);
  return out;
}

RecordedFrames read_recording(SidecarReader& in) {
  RecordedFrames r;
  r.prefracture = in.value<std::int32_t>();
  r.runtime = in.value<std::int32_t>();
  r.repetition = in.value<std::int32_t>();
  const auto frames = in.value<std::uint32_t>();
  r.seed = in.value<std::uint64_t>();
  const auto meshes = in.value<std::uint32_t>();
  const auto bodies = in.value<std::uint32_t>();
  const auto stage_mask = in.value<std::uint32_t>();
  const auto reserved = in.value<std::uint32_t>();
  require(in.ok() && reserved == 0 && stage_mask >> kStageCount == 0, "recording header");
  require(r.prefracture >= 0 && r.runtime >= 0 && r.repetition >= 0 && frames <= kMaxFrames, "recording header");
  r.frames = static_cast<int>(frames);
  require(in.fits(frames, 8), "frame times");
  r.frame_ms = read_times(in, frames, "frame times");
  for (std::size_t s = 0; s < kStageCount; ++s)
    if (stage_mask & (1u << s)) {
      require(in.fits(frames, 8), "stage times");
      r.stage_ms[s] = read_times(in, frames, "stage times");
    }
  require(in.fits(meshes, 40), "meshes");
  for (std::uint32_t i = 0; i < meshes; ++i) r.meshes.push_back(read_mesh_entry(in));
  require(in.fits(bodies, 28), "bodies");
  for (std::uint32_t i = 0; i < bodies; ++i) r.bodies.push_back(read_body_entry(in, meshes));
  require(in.padding(4), "bodies");
  const std::uint64_t poses = static_cast<std::uint64_t>(frames) * bodies;
  require(poses <= static_cast<std::uint64_t>(kMaxRecordedPoses) && in.fits(poses, 20), "poses");
  r.poses.resize(static_cast<std::size_t>(poses));
  read_poses(in, r);
  return r;
}

}  // namespace

std::filesystem::path recorded_frames_beside(const std::filesystem::path& json) {
  std::filesystem::path out = json;
  out.replace_extension(".frames.bin");
  return out;
}

std::string encode_recorded_frames(std::span<const RecordedFrames> recordings) {
  std::vector<std::string> blocks;
  for (const RecordedFrames& r : recordings) blocks.push_back(recording_block(r));
  BinaryWriter w;
  w.bytes(kMagic, sizeof kMagic);
  w.value(kVersion);
  w.value(static_cast<std::uint32_t>(blocks.size()));
  std::uint64_t offset = sizeof kMagic + 8 + 16 * blocks.size();
  for (const std::string& b : blocks) {
    w.value(offset);
    w.value(static_cast<std::uint64_t>(b.size()));
    offset += b.size();
  }
  std::string out = w.data();
  for (const std::string& b : blocks) out += b;
  return out;
}

Result<std::vector<RecordedFrames>> decode_recorded_frames(const std::string& bytes, const std::string& what) {
  SidecarReader in(bytes);
  char magic[sizeof kMagic] = {};
  in.bytes(magic, sizeof magic);
  if (!in.ok() || !std::equal(magic, magic + sizeof magic, kMagic))
    return Error{what + ": not a recorded-frames file (no SBFRAMES header)"};
  const auto version = in.value<std::uint32_t>();
  if (version != kVersion)
    return Error{fmt::format("{}: recorded-frames version {} is not supported (this build reads {})", what, version,
                             kVersion)};
  const auto count = in.value<std::uint32_t>();
  if (!in.fits(count, 16)) return Error{what + ": the table of recordings is cut short"};
  std::vector<std::pair<std::uint64_t, std::uint64_t>> table(count);
  for (auto& [offset, size] : table) {
    offset = in.value<std::uint64_t>();
    size = in.value<std::uint64_t>();
  }
  std::vector<RecordedFrames> out;
  for (std::uint32_t k = 0; k < count; ++k) {
    try {
      require(table[k].first == in.position() && table[k].second <= bytes.size() - in.position(), "offset");
      out.push_back(read_recording(in));
      require(in.position() - table[k].first == table[k].second, "size");
    } catch (const Bad& bad) {
      return Error{fmt::format("{}: recording {}: {}: not as written (cut short, damaged or not a sidecar)", what, k,
                               bad.part)};
    }
  }
  if (!in.at_end()) return Error{what + ": bytes after the last recording"};
  return out;
}

Result<std::vector<RecordedFrames>> read_recorded_frames(const std::filesystem::path& path) {
  const Result<std::string> bytes = read_file_bounded(path, kMaxResultsFileBytes, "recorded frames");
  if (!bytes) return bytes.error();
  return decode_recorded_frames(*bytes, path.string());
}

}  // namespace shatter
