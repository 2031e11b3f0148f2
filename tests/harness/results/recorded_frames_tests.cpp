// The recorded-frames sidecar: what is encoded decodes to the same recording within the documented
// quantisation, its size is the documented one, and bytes that are not a whole sidecar are an error.

#include "harness/results/recorded_frames.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace shatter;

/// A tetrahedron of size `size` at `at`.
RecordedMesh tetrahedron(float size, std::array<float, 3> at, int fragment, int piece) {
  RecordedMesh m;
  m.fragment = fragment;
  m.piece = piece;
  m.vertices = {at, {at[0] + size, at[1], at[2]}, {at[0], at[1] + size, at[2]}, {at[0], at[1], at[2] + size}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

std::array<float, 4> unit_quaternion(std::mt19937& rng) {
  std::normal_distribution<float> n;
  std::array<float, 4> q{n(rng), n(rng), n(rng), n(rng)};
  const float norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (float& c : q) c /= norm;
  return q;
}

/// Two meshes, three bodies (a fragment, a piece, a cluster of both fragments) over `frames` frames.
RecordedFrames recording(int frames) {
  RecordedFrames r;
  r.prefracture = 10;
  r.runtime = 5;
  r.repetition = 0;
  r.seed = 42;
  r.frames = frames;
  for (int f = 0; f < frames; ++f) r.frame_ms.push_back(1.0 + f / 3.0);
  r.stage_ms[static_cast<std::size_t>(Stage::physics)].assign(static_cast<std::size_t>(frames), 0.25);
  r.meshes = {tetrahedron(2.0f, {1, 2, 3}, 0, -1), tetrahedron(0.1f, {-4, 0, 8}, 3, 2)};
  r.bodies.resize(3);
  r.bodies[0] = {RecordedBodyKind::fragment, 0, -1, {0}, {1.5f, 2.5f, 3.5f}};
  r.bodies[1] = {RecordedBodyKind::piece, 3, 2, {1}, {-3.975f, 0.025f, 8.025f}};
  r.bodies[2] = {RecordedBodyKind::cluster, -1, -1, {0, 1}, {0.0f, 1.0f, 2.0f}};
  std::mt19937 rng(7);
  for (int f = 0; f < frames; ++f)
    for (int b = 0; b < 3; ++b) {
      BodyPose p;
      p.position = {0.5f * f, -1000.25f + b, 3.0f};
      p.rotation = unit_quaternion(rng);
      p.scale = b == 1 ? 1.0f - static_cast<float>(f) / frames : 1.0f;
      p.flags = static_cast<std::uint8_t>(f % 16);
      r.poses.push_back(p);
    }
  return r;
}

/// The angle between the rotations of unit quaternions `a` and `b`, rad: |a - b| = 2 sin(angle / 4)
/// with the sign of b that makes them closest (acos of their dot product would lose it to round-off).
double angle_between(const std::array<float, 4>& a, const std::array<float, 4>& b) {
  double dot = 0.0;
  for (int i = 0; i < 4; ++i) dot += static_cast<double>(a[i]) * b[i];
  const double sign = dot < 0.0 ? -1.0 : 1.0;
  double d = 0.0;
  for (int i = 0; i < 4; ++i) d += (a[i] - sign * b[i]) * (a[i] - sign * b[i]);
  return 4.0 * std::asin(std::min(1.0, std::sqrt(d) / 2.0));
}

}  // namespace

TEST_CASE("recorded frames: a recording decodes as encoded, within the quantisation", "[results][record-frames]") {
  const std::vector<RecordedFrames> in = {recording(7), recording(3)};
  const std::string bytes = encode_recorded_frames(in);
  const Result<std::vector<RecordedFrames>> out = decode_recorded_frames(bytes, "r.frames.bin");
  REQUIRE(out);
  REQUIRE(out->size() == 2);
  for (std::size_t k = 0; k < 2; ++k) {
    const RecordedFrames& a = in[k];
    const RecordedFrames& b = (*out)[k];
    CHECK(b.prefracture == a.prefracture);
    CHECK(b.seed == a.seed);
    CHECK(b.frames == a.frames);
    CHECK(b.frame_ms == a.frame_ms);
    CHECK(b.stage_ms == a.stage_ms);
    REQUIRE(b.meshes.size() == a.meshes.size());
    for (std::size_t m = 0; m < a.meshes.size(); ++m) {
      CHECK(b.meshes[m].fragment == a.meshes[m].fragment);
      CHECK(b.meshes[m].piece == a.meshes[m].piece);
      CHECK(b.meshes[m].triangles == a.meshes[m].triangles);
      REQUIRE(b.meshes[m].vertices.size() == a.meshes[m].vertices.size());
      const float size = a.meshes[m].vertices[1][0] - a.meshes[m].vertices[0][0];
      for (std::size_t v = 0; v < a.meshes[m].vertices.size(); ++v)
        for (int c = 0; c < 3; ++c)
          CHECK(std::abs(b.meshes[m].vertices[v][c] - a.meshes[m].vertices[v][c]) <= size / 65535.0f + 1e-5f);
    }
    REQUIRE(b.bodies.size() == a.bodies.size());
    for (std::size_t i = 0; i < a.bodies.size(); ++i) {
      CHECK(b.bodies[i].kind == a.bodies[i].kind);
      CHECK(b.bodies[i].fragment == a.bodies[i].fragment);
      CHECK(b.bodies[i].piece == a.bodies[i].piece);
      CHECK(b.bodies[i].meshes == a.bodies[i].meshes);
      CHECK(b.bodies[i].rest_centroid == a.bodies[i].rest_centroid);
    }
    REQUIRE(b.poses.size() == a.poses.size());
    for (std::size_t i = 0; i < a.poses.size(); ++i) {
      CHECK(b.poses[i].position == a.poses[i].position);  // float32, exact
      CHECK(b.poses[i].flags == a.poses[i].flags);
      CHECK(std::abs(b.poses[i].scale - a.poses[i].scale) <= 0.5f / 255.0f + 1e-6f);
      CHECK(angle_between(b.poses[i].rotation, a.poses[i].rotation) < 1e-4);
    }
  }
}

TEST_CASE("recorded frames: a rotation keeps 1e-4 rad over many random ones", "[results][record-frames]") {
  RecordedFrames r = recording(1);
  std::mt19937 rng(11);
  r.poses.clear();
  r.frames = 1;
  r.frame_ms = {1.0};
  r.stage_ms = {};
  r.bodies.assign(2000, r.bodies[0]);
  for (std::size_t i = 0; i < r.bodies.size(); ++i) r.poses.push_back({{0, 0, 0}, unit_quaternion(rng), 1.0f, 1});
  r.poses[0].rotation = {0, 0, 0, 1};
  r.poses[1].rotation = {0, 0, 0, -1};               // the same rotation as +w
  r.poses[2].rotation = {0.70710677f, 0, 0, 0.70710677f};  // two components tie for largest
  const std::vector<RecordedFrames> in = {r};
  const auto out = decode_recorded_frames(encode_recorded_frames(in), "r");
  REQUIRE(out);
  double worst = 0.0;
  for (std::size_t i = 0; i < r.poses.size(); ++i)
    worst = std::max(worst, angle_between((*out)[0].poses[i].rotation, r.poses[i].rotation));
  CHECK(worst < 1e-4);
}

TEST_CASE("recorded frames: the size is 20 bytes a pose plus the documented headers and meshes", "[results][record-frames]") {
  const RecordedFrames r = recording(50);
  const std::vector<RecordedFrames> in = {r};
  const std::string bytes = encode_recorded_frames(in);
  // docs/results.md: 16 + 16 per recording; per recording 40, 8 per frame and per frame and stage
  // column, per mesh 40 + 6 per vertex + 6 per triangle (12 past 65,536 vertices) padded to 4, per
  // body 28 + 4 per mesh, 20 per pose, padding to 8 at the end.
  std::size_t expected = 16 + 16 + 40 + 8 * 50 * 2;
  for (const RecordedMesh& m : r.meshes) expected += 40 + (6 * m.vertices.size() + 3) / 4 * 4 + (6 * m.triangles.size() + 3) / 4 * 4;
  for (const RecordedBody& b : r.bodies) expected += 28 + 4 * b.meshes.size();
  expected = (expected + 3) / 4 * 4 + 20 * 3 * 50;
  expected = (expected + 7) / 8 * 8;
  CHECK(bytes.size() == expected);
}

TEST_CASE("recorded frames: bytes that are not a whole sidecar are an error, never a crash", "[results][record-frames]") {
  const std::vector<RecordedFrames> in = {recording(4)};
  const std::string bytes = encode_recorded_frames(in);
  for (std::size_t n = 0; n < bytes.size(); n += 7) {
    const auto r = decode_recorded_frames(bytes.substr(0, n), "cut.bin");
    REQUIRE_FALSE(r);
    CHECK(r.error().message.rfind("cut.bin: ", 0) == 0);
  }
  CHECK_FALSE(decode_recorded_frames(bytes + "x", "long.bin"));
  std::string wrong = bytes;
  wrong[0] = 'X';
  CHECK(decode_recorded_frames(wrong, "w.bin").error().message ==
        "w.bin: not a recorded-frames file (no SBFRAMES header)");
  // Every single-byte change either decodes to something valid or is refused; none crashes.
  std::mt19937 rng(3);
  for (int trial = 0; trial < 2000; ++trial) {
    std::string damaged = bytes;
    damaged[rng() % damaged.size()] = static_cast<char>(rng());
    (void)decode_recorded_frames(damaged, "d.bin");
  }
}
