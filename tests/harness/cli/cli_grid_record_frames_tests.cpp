// `shatterbench grid --record-frames`: the sidecar beside the JSON reads back with every body in every
// frame, the first frame where the pieces were made and the results' body count at the end; past the
// limit, or with flags it cannot serve, exit 2 with one line and nothing written; a bigger cell stays
// within the size docs/results.md gives.

#include "harness/results/recorded_frames.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <string>

namespace {

using namespace shatter;
using shatter::test::line_count;
using shatter::test::run_cli;
using shatter::test::slurp;
using Json = nlohmann::json;

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "shatter_grid_tests" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The volume centroid of a closed mesh (divergence theorem over tetrahedra from the first vertex).
std::array<double, 3> mesh_centroid(const RecordedMesh& m) {
  const auto& o = m.vertices[0];
  double volume = 0.0;
  std::array<double, 3> c{};
  for (const auto& t : m.triangles) {
    std::array<std::array<double, 3>, 3> p;
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) p[k][a] = static_cast<double>(m.vertices[t[k]][a]) - o[a];
    const double v = (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                      p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) / 6.0;
    volume += v;
    for (int a = 0; a < 3; ++a) c[a] += v * (p[0][a] + p[1][a] + p[2][a]) / 4.0;
  }
  for (int a = 0; a < 3; ++a) c[a] = c[a] / volume + o[a];
  return c;
}

/// The size docs/results.md gives for `recordings` ("Recorded frames"): 16 + 16 per recording, and per
/// recording 40, 8 per frame and per frame of each stage column, per mesh 40 + 6 per vertex + 6 per
/// triangle (12 past 65,536 vertices) + up to 6 of padding, per body 28 + 4 per mesh, 20 per pose and
/// up to 10 of padding.
std::uint64_t documented_bound(const std::vector<RecordedFrames>& recordings) {
  std::uint64_t bytes = 16 + 16 * recordings.size();
  for (const RecordedFrames& r : recordings) {
    std::uint64_t columns = 1;
    for (const auto& c : r.stage_ms) columns += c.empty() ? 0 : 1;
    bytes += 40 + 8 * columns * static_cast<std::uint64_t>(r.frames) + 20 * r.poses.size() + 10;
    for (const RecordedMesh& m : r.meshes)
      bytes += 40 + 6 * m.vertices.size() + (m.vertices.size() > 65536 ? 12 : 6) * m.triangles.size() + 6;
    for (const RecordedBody& b : r.bodies) bytes += 28 + 4 * b.meshes.size();
  }
  return bytes;
}

}  // namespace

TEST_CASE("cli: grid --record-frames writes every body in every frame beside the JSON", "[cli][grid][record-frames]") {
  const auto dir = scratch("record_frames");
  const auto json = dir / "grid.json";
  const auto r = run_cli("grid --case building --prefracture 10 --runtime 5 --frames 30 --repetitions 1 --no-cache "
                         "--record-frames --json " + json.string());
  INFO(r.err);
  REQUIRE((r.exit_code == 0 || r.exit_code == 1));
  const auto sidecar = dir / "grid.frames.bin";
  REQUIRE(std::filesystem::exists(sidecar));
  const Json j = Json::parse(slurp(json));
  const Json& block = j.at("recorded_frames");
  CHECK(block.at("path") == "grid.frames.bin");
  CHECK(block.at("bytes").get<std::uintmax_t>() == std::filesystem::file_size(sidecar));

  const Result<std::vector<RecordedFrames>> read = read_recorded_frames(sidecar);
  REQUIRE(read);
  REQUIRE(read->size() == 1);
  const RecordedFrames& rec = read->front();
  CHECK(rec.prefracture == 10);
  CHECK(rec.runtime == 5);
  CHECK(rec.seed == j.at("cells")[0].at("samples")[0].at("seed").get<std::uint64_t>());
  REQUIRE(rec.frames == 30);
  REQUIRE(rec.poses.size() == rec.bodies.size() * 30);
  CHECK(block.at("recordings")[0].at("bodies").get<std::size_t>() == rec.bodies.size());
  const Json& sample = j.at("cells")[0].at("samples")[0];
  for (std::size_t f = 0; f < 30; ++f) CHECK(rec.frame_ms[f] == sample.at("frame_ms")[f].get<double>());

  // The first frame: each body there is a pre-fracture fragment at its mesh's centroid (where the
  // pieces were made), and every pre-fracture fragment is there.
  int first = 0;
  for (std::size_t b = 0; b < rec.bodies.size(); ++b) {
    const BodyPose& pose = rec.pose(0, static_cast<int>(b));
    if (!(pose.flags & kPosePresent)) continue;
    ++first;
    REQUIRE(rec.bodies[b].kind == RecordedBodyKind::fragment);
    const std::array<double, 3> c = mesh_centroid(rec.meshes.at(rec.bodies[b].meshes.at(0)));
    for (int a = 0; a < 3; ++a) {
      CHECK(pose.position[a] == rec.bodies[b].rest_centroid[a]);
      CHECK(std::abs(pose.position[a] - c[a]) < 1e-3);  // the mesh's quantisation, 1/65,535 of its size
    }
  }
  CHECK(first == sample.at("fragments").get<int>());
  // The last frame holds the results' bodies.
  int last = 0;
  for (std::size_t b = 0; b < rec.bodies.size(); ++b) last += (rec.pose(29, static_cast<int>(b)).flags & kPosePresent) ? 1 : 0;
  CHECK(last == sample.at("bodies").get<int>());

  // Run again into the same files: the sidecar is shatterbench's own, so it is replaced; a file of
  // the user's with that name is not.
  const auto again = run_cli("grid --case building --prefracture 10 --runtime 5 --frames 30 --repetitions 1 --no-cache "
                             "--record-frames --json " + json.string());
  INFO(again.err);
  CHECK((again.exit_code == 0 || again.exit_code == 1));
  std::filesystem::resize_file(sidecar, 4);  // "SBFR": no longer the magic
  const auto refused = run_cli("grid --case building --prefracture 10 --runtime 5 --frames 30 --repetitions 1 --no-cache "
                               "--record-frames --json " + json.string());
  CHECK(refused.exit_code == 2);
  CHECK(refused.err.find("not replaced") != std::string::npos);
  CHECK(std::filesystem::file_size(sidecar) == 4);
}

TEST_CASE("cli: grid --record-frames past its limit or with flags it cannot serve: exit 2, one line, nothing written",
          "[cli][grid][record-frames]") {
  const auto dir = scratch("record_frames_bad");
  const std::string json = (dir / "grid.json").string();
  struct Bad {
    std::string args;
    std::string words;
  };
  const Bad cases[] = {
      // 30 fragments in the first of 100,000 frames are 3,000,000 poses: past kMaxRecordedPoses.
      {"--prefracture 30 --runtime 5 --frames 100000 --json " + json, "exceed the limit of 2000000"},
      {"--prefracture 10 --runtime 5 --frames 10", "needs --json"},
      {"--prefracture 10 --runtime 5 --frames 10 --timeout 60 --json " + json, "--timeout"},
      {"--prefracture 10 --runtime 5 --frames 10 --metric instructions --json " + json, "--metric instructions"},
  };
  for (const Bad& b : cases) {
    const auto r = run_cli("grid --case building --repetitions 1 --no-cache --record-frames " + b.args);
    INFO(b.args << "\n" << r.err);
    REQUIRE(r.exit_code == 2);
    REQUIRE(line_count(r.err) == 1);
    REQUIRE(r.err.find(b.words) != std::string::npos);
    REQUIRE(std::filesystem::is_empty(dir));
  }
}

TEST_CASE("cli: grid --record-frames of a bigger cell stays within the documented size", "[cli][grid][record-frames]") {
  const auto dir = scratch("record_frames_big");
  const auto json = dir / "grid.json";
  const auto r = run_cli("grid --case building --prefracture 100 --runtime 25 --frames 300 --repetitions 1 "
                         "--record-frames --json " + json.string());
  INFO(r.err);
  REQUIRE((r.exit_code == 0 || r.exit_code == 1));
  const auto sidecar = dir / "grid.frames.bin";
  const Result<std::vector<RecordedFrames>> read = read_recorded_frames(sidecar);
  REQUIRE(read);
  const RecordedFrames& rec = read->front();
  REQUIRE(rec.bodies.size() > 100);
  const std::uintmax_t size = std::filesystem::file_size(sidecar);
  CHECK(size <= documented_bound(*read));
  CHECK(20 * rec.poses.size() <= size);  // the poses are stored whole
}
