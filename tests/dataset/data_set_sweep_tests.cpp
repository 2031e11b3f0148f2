// Every mesh of CGAL's data set, as a user brings it: each one that encloses a volume is repaired into a
// solid (when it is not one already) and fractures with every fracturer into closed fragments that
// conserve the repaired solid's volume and partition it; each one that encloses none is refused with
// its reason. Which meshes enclose no volume is written down, with the reason, in
// tests/fixtures/data_set_without_solid.tsv: a mesh outside that list that is refused fails, and so
// does a listed mesh that loads.
//
// With SHATTER_WRITE_DATA_SET_TABLE=FILE the table of the sweep (docs/data-set-sweep.md) is written to
// FILE by the test "data set: the sweep table" (hidden: `build/bin/shatter_tests "[.data-set-table]"`).

#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/solid_check.h"
#include "algorithms/fracture/fracturer.h"
#include "harness/cases/load_solid.h"
#include "harness/metrics/fracture_metrics.h"
#include "tests/support/builtin_registries.h"
#include "tests/support/mesh_fixtures.h"

#include <catch2/catch.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace shatter;

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> data_set() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(test::mesh_dir()))
    if (e.path().extension() == ".off") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

/// mesh file name -> the words its refusal must contain.
std::map<std::string, std::string> meshes_without_solid() {
  std::map<std::string, std::string> out;
  std::ifstream in(fs::path(SHATTER_SOURCE_DIR) / "tests" / "fixtures" / "data_set_without_solid.tsv");
  REQUIRE(in.good());
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    REQUIRE(tab != std::string::npos);
    out[line.substr(0, tab)] = line.substr(tab + 1);
  }
  REQUIRE_FALSE(out.empty());
  return out;
}

/// The fragment counts of the sweep: cgal-clip, the exact reference, at 5 and 25 (its time grows
/// fastest with the count), every other fracturer at 5, 25 and 100.
std::vector<int> counts_for(const std::string& fracturer) {
  return fracturer == "cgal-clip" ? std::vector<int>{5, 25} : std::vector<int>{5, 25, 100};
}

/// What one fracturer did with one solid over the sweep's counts.
struct SweepVerdict {
  std::string failure;      ///< "" when every count passes the bars, else what failed first
  int fragments = 0;        ///< fragments made over all counts
  int off_rule = 0;         ///< of those, fragments the full acceptance rule refuses (check_solid)
  std::string first_off;    ///< check_solid's reason for the first of them
};

/// Runs `fracturer` on `solid` at every count of the sweep: the bars are closed fragments (all_closed),
/// volume error <= 1e-9 against the solid and partition error 0. Fragments that the full acceptance
/// rule refuses (a self-intersection made by rounding) are counted, not failed: docs/repair.md,
/// "Known gaps".
SweepVerdict sweep_solid(const Fracturer& fracturer, const std::string& name, const Solid& solid) {
  SweepVerdict v;
  for (const int n : counts_for(name)) {
    FractureParams params;
    params.fragments = n;
    params.seed = 11;
    auto fragments = fracturer.fracture(solid.mesh, params);
    if (!fragments) {
      v.failure = fmt::format("{} fragments: refused: {}", n, fragments.error().message);
      return v;
    }
    const FractureMetrics m = fracture_metrics(solid.mesh, solid.mass, *fragments, n,
                                               FractureMetricsOptions{.partition_samples = 500, .seed = 5});
    if (!m.all_closed) v.failure = fmt::format("{} fragments: {}", n, m.fragment_problem);
    else if (!(m.volume_error <= 1e-9)) v.failure = fmt::format("{} fragments: volume_error {:.3g}", n, m.volume_error);
    else if (m.partition_error != 0.0) v.failure = fmt::format("{} fragments: partition_error {:.3g}", n, m.partition_error);
    else if (m.fragment_count < 1) v.failure = fmt::format("{} fragments: no fragment", n);
    if (!v.failure.empty()) return v;
    for (const Fragment& f : *fragments) {
      ++v.fragments;
      if (Status s = check_solid(f.mesh, "fragment", nullptr); !s) {
        if (v.off_rule++ == 0) v.first_off = fmt::format("{} fragments: {}", n, s.error().message);
      }
    }
  }
  return v;
}

/// One mesh: refused with the listed reason, or loaded and passing `fracturer` at every count.
void check_mesh(const fs::path& path, const std::map<std::string, std::string>& without_solid,
                const std::string& fracturer_name, const Fracturer& fracturer) {
  const std::string file = path.filename().string();
  INFO(file << " with " << fracturer_name);
  Result<Solid> solid = load_solid(path);
  const auto listed = without_solid.find(file);
  if (listed != without_solid.end()) {
    REQUIRE_FALSE(solid.ok());
    CHECK(solid.error().message.find('\n') == std::string::npos);
    CHECK_THAT(solid.error().message, Catch::Contains(listed->second));
    return;
  }
  if (!solid) FAIL("refused: " << solid.error().message);
  const SweepVerdict v = sweep_solid(fracturer, fracturer_name, *solid);
  CHECK(v.failure == "");
  if (v.off_rule > 0) WARN(v.off_rule << " of " << v.fragments << " fragments refused by check_solid: " << v.first_off);
}

/// Every mesh of the data set through one fracturer; `part`/`parts` split the meshes so that ctest
/// runs the parts side by side.
void sweep(const std::string& fracturer_name, int part, int parts) {
  if (!test::have_meshes()) return;
  const auto without_solid = meshes_without_solid();
  const Registries registries = test::builtin_registries();
  auto fracturer = registries.fracturers.create(fracturer_name);
  REQUIRE(fracturer.ok());
  const std::vector<fs::path> meshes = data_set();
  // The data set is the whole of libcgal-demo's meshes: a partial folder would pass with less.
  REQUIRE(meshes.size() >= 138);
  for (const auto& [file, reason] : without_solid) CHECK(fs::exists(test::mesh_dir() / file));
  for (std::size_t i = static_cast<std::size_t>(part); i < meshes.size(); i += static_cast<std::size_t>(parts))
    check_mesh(meshes[i], without_solid, fracturer_name, **fracturer);
}

}  // namespace

TEST_CASE("data set: plane-slice fractures every mesh that encloses a volume", "[data-set][plane-slice][slow]") {
  sweep("plane-slice", 0, 1);
}

TEST_CASE("data set: voronoi fractures every mesh that encloses a volume", "[data-set][voronoi][slow]") {
  sweep("voronoi", 0, 1);
}

TEST_CASE("data set: fem-lite fractures every mesh that encloses a volume", "[data-set][fem-lite][slow]") {
  sweep("fem-lite", 0, 1);
}

TEST_CASE("data set: cgal-clip fractures every mesh that encloses a volume (1 of 3)", "[data-set][cgal-clip][slow]") {
  sweep("cgal-clip", 0, 3);
}

TEST_CASE("data set: cgal-clip fractures every mesh that encloses a volume (2 of 3)", "[data-set][cgal-clip][slow]") {
  sweep("cgal-clip", 1, 3);
}

TEST_CASE("data set: cgal-clip fractures every mesh that encloses a volume (3 of 3)", "[data-set][cgal-clip][slow]") {
  sweep("cgal-clip", 2, 3);
}

TEST_CASE("data set: the sweep table", "[.data-set-table]") {
  const char* out = std::getenv("SHATTER_WRITE_DATA_SET_TABLE");
  REQUIRE(out != nullptr);
  REQUIRE(test::have_meshes());
  const Registries registries = test::builtin_registries();
  const std::vector<std::string> names = {"plane-slice", "voronoi", "fem-lite", "cgal-clip"};
  std::ostringstream table;
  table << "| mesh | triangles | repairs | Hausdorff / diagonal |";
  for (const auto& n : names) table << ' ' << n << " |";
  table << "\n|---|---|---|---|";
  for (std::size_t i = 0; i < names.size(); ++i) table << "---|";
  table << '\n';
  for (const fs::path& path : data_set()) {
    const std::string file = path.filename().string();
    Result<Solid> solid = load_solid(path);
    if (!solid) {
      std::string reason = solid.error().message;
      // "<path>: why" or "<path>:<line>: why" -> "why" or "line <line>: why".
      if (reason.rfind(path.string() + ":", 0) == 0) {
        reason = reason.substr(path.string().size() + 1);
        if (!reason.empty() && reason[0] == ' ') reason = reason.substr(1);
        else if (!reason.empty() && std::isdigit(static_cast<unsigned char>(reason[0]))) reason = "line " + reason;
      }
      table << "| " << file << " | | refused: " << reason << " | |";
      for (std::size_t k = 0; k < names.size(); ++k) table << " |";
      table << '\n';
      continue;
    }
    const RepairReport& r = solid->repair;
    std::vector<std::string> did;
    const int merged = r.vertices_merged + solid->report.merged_duplicate_vertices;
    if (merged) did.push_back(fmt::format("{} vertices merged", merged));
    if (solid->report.flipped) did.push_back("flipped");
    if (r.faces_removed) did.push_back(fmt::format("{} faces removed", r.faces_removed));
    if (r.faces_reoriented) did.push_back(fmt::format("{} faces reoriented", r.faces_reoriented));
    if (r.holes_filled) did.push_back(fmt::format("{} holes filled", r.holes_filled));
    if (r.self_intersections) did.push_back(fmt::format("{} intersecting pairs ({})", r.self_intersections, r.self_intersection_fix));
    if (r.sheets_removed) did.push_back(fmt::format("{} sheets removed", r.sheets_removed));
    if (solid->report.cavities) did.push_back(fmt::format("{} cavities", solid->report.cavities));
    std::string repairs;
    for (const std::string& d : did) repairs += (repairs.empty() ? "" : ", ") + d;
    const double diagonal = bounding_box(solid->mesh).diagonal();
    table << "| " << file << " | " << solid->mesh.triangle_count() << " | " << (repairs.empty() ? "none" : repairs)
          << " | " << (r.repaired ? fmt::format("{:.2e}", r.hausdorff_distance / diagonal) : std::string("0")) << " |";
    for (const std::string& n : names) {
      auto fracturer = registries.fracturers.create(n);
      REQUIRE(fracturer.ok());
      const SweepVerdict v = sweep_solid(**fracturer, n, *solid);
      std::string cell = v.failure.empty() ? std::string("ok") : "FAILED: " + v.failure;
      if (v.failure.empty() && v.off_rule > 0) cell += fmt::format(" ({} of {} fragments intersect themselves)", v.off_rule, v.fragments);
      table << ' ' << cell << " |";
    }
    table << '\n';
  }
  std::ofstream(out) << table.str();
}
