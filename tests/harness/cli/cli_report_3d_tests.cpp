// `shatterbench report` with what its 3D views show: fragments folders (fracture --out, table --out)
// and a grid's recorded frames; and the bad input of each: a truncated or altered glTF binary, an image
// reference out of the folder, a missing sidecar, more fragments than the page takes.

#include "harness/limits.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

using shatter::test::run_cli_argv;
using shatter::test::slurp;
namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const auto dir = fs::temp_directory_path() / "shatter_report_3d_tests" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

const char* const kCube = "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                          "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n"
                          "3 3 0 4\n3 3 4 7\n";

void write(const fs::path& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

/// A glTF binary of `json` and `bin` (padded as the format asks).
std::string glb(std::string json, std::string bin) {
  while (json.size() % 4) json += ' ';
  while (bin.size() % 4) bin += '\0';
  const auto u32 = [](std::uint32_t v) {
    std::string s(4, '\0');
    for (int i = 0; i < 4; ++i) s[static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xff);
    return s;
  };
  std::string out = "glTF" + u32(2) + u32(static_cast<std::uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
  out += u32(static_cast<std::uint32_t>(json.size())) + "JSON" + json;
  if (!bin.empty()) out += u32(static_cast<std::uint32_t>(bin.size())) + std::string("BIN\0", 4) + bin;
  return out;
}

/// The report page's data, parsed from its script element.
nlohmann::json page_data(const fs::path& html) {
  const std::string page = slurp(html);
  const std::string open = "id=\"shatterbench-data\">";
  const auto start = page.find(open);
  REQUIRE(start != std::string::npos);
  const auto end = page.find("</script>", start);
  return nlohmann::json::parse(page.substr(start + open.size(), end - start - open.size()));
}

}  // namespace

TEST_CASE("cli: table --out and fracture --out write fragments folders that report embeds, labelled", "[cli][report]") {
  const auto dir = scratch("folders");
  write(dir / "cube.off", kCube);
  const auto t = run_cli_argv({"table", "--mesh", (dir / "cube.off").string(), "--algo", "plane-slice", "voronoi",
                               "--fragments", "4", "--repetitions", "1", "--out", (dir / "rows").string()});
  INFO(t.err);
  REQUIRE(t.exit_code == 0);
  for (const char* algo : {"plane-slice", "voronoi"}) {
    const fs::path row = dir / "rows" / "0-cube.off" / "4" / algo;
    INFO(row);
    REQUIRE(fs::exists(row / "fragments.glb"));
    const auto summary = nlohmann::json::parse(slurp(row / "fracture.json"));
    CHECK(summary["kind"] == "fracture");
    CHECK(summary["algorithm"] == algo);
    CHECK(summary["seed"] == 1);
    CHECK(summary["requested"] == 4);
  }
  const auto f = run_cli_argv({"fracture", "--mesh", (dir / "cube.off").string(), "--algo", "voronoi", "--fragments", "5",
                               "--seed", "7", "--out", (dir / "one").string()});
  INFO(f.err);
  REQUIRE(f.exit_code == 0);
  const auto printed = nlohmann::json::parse(f.out);
  const auto summary = nlohmann::json::parse(slurp(dir / "one" / "fracture.json"));
  CHECK(summary["fragments"] == printed["fragments"]);  // what was printed is what the folder says
  CHECK(summary["seed"] == 7);

  const auto out = dir / "report";
  const auto r = run_cli_argv({"report", (dir / "rows").string(), (dir / "one").string(), "--out", out.string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("3 fragments folder(s)") != std::string::npos);
  const nlohmann::json data = page_data(out / "report.html");
  REQUIRE(data["fragments"].size() == 3);
  for (const auto& e : data["fragments"]) {
    CHECK(e["mesh"] == "cube.off");
    CHECK(e["glb"].get<std::string>().size() > 100);
    CHECK(e["fragments"].get<int>() == e["summary"]["fragments"].get<int>());  // one glTF node per fragment
  }
}

TEST_CASE("cli: report refuses a bad fragments folder or recording with one line and writes nothing", "[cli][report]") {
  const auto dir = scratch("bad");
  write(dir / "cube.off", kCube);
  const auto f = run_cli_argv({"fracture", "--mesh", (dir / "cube.off").string(), "--algo", "plane-slice", "--fragments",
                               "3", "--out", (dir / "good").string()});
  REQUIRE(f.exit_code == 0);
  const std::string good_glb = slurp(dir / "good" / "fragments.glb");
  const std::string summary = slurp(dir / "good" / "fracture.json");
  const auto folder = [&](const std::string& name, const std::string& glb_bytes, const std::string& summary_text) {
    fs::create_directories(dir / name);
    write(dir / name / "fragments.glb", glb_bytes);
    write(dir / name / "fracture.json", summary_text);
    return (dir / name).string();
  };
  std::string altered = good_glb;
  altered[4] = 3;  // version 3
  const std::string image_out = glb(R"({"asset":{"version":"2.0"},"images":[{"uri":"../../secret.png"}]})", "");
  std::string many_nodes = R"({"asset":{"version":"2.0"},"nodes":[)";
  for (std::int64_t i = 0; i <= shatter::kMaxReportFragments; ++i) many_nodes += i ? ",{}" : "{}";
  many_nodes += "]}";
  const std::string past_view = glb(R"({"asset":{"version":"2.0"},"bufferViews":[{"buffer":0,"byteLength":64}]})", std::string(8, '\0'));
  const std::pair<std::string, std::string> cases[] = {
      {folder("truncated", good_glb.substr(0, good_glb.size() / 2), summary), "truncated"},
      {folder("version", altered, summary), "glTF binary version 3"},
      {folder("image", image_out, summary), "secret.png"},
      {folder("many", glb(many_nodes, ""), summary), "past the report's limit"},
      {folder("view", past_view, summary), "bufferViews[0]"},
      {folder("summary", good_glb, R"({"kind": "table"})"), "fracture.json: kind"},
      {(dir / "empty").string(), "no fragments folder"},
  };
  fs::create_directories(dir / "empty");
  const auto out = dir / "report";
  for (const auto& [input, words] : cases) {
    INFO(input);
    const auto r = run_cli_argv({"report", input, "--out", out.string()});
    CHECK(r.exit_code == 2);
    CHECK(shatter::test::line_count(r.err) == 1);
    CHECK(r.err.find(words) != std::string::npos);
    CHECK_FALSE(fs::exists(out));
  }

  // A grid whose recording is missing, or names a file outside its folder.
  const auto grid = dir / "grid.json";
  const auto g = run_cli_argv({"grid", "--case", "building", "--prefracture", "10", "--runtime", "5", "--frames", "5",
                               "--repetitions", "1", "--no-cache", "--record-frames", "--json", grid.string()});
  INFO(g.err);
  REQUIRE(g.exit_code == 0);
  auto doc = nlohmann::json::parse(slurp(grid));
  doc["recorded_frames"]["path"] = "../outside.frames.bin";
  write(dir / "outside.json", doc.dump());
  fs::rename(dir / "grid.frames.bin", dir / "moved.frames.bin");
  for (const auto& [input, words] : {std::pair<std::string, std::string>{grid.string(), "grid.frames.bin"},
                                     {(dir / "outside.json").string(), "outside.frames.bin"}}) {
    INFO(input);
    const auto r = run_cli_argv({"report", input, "--out", out.string()});
    CHECK(r.exit_code == 2);
    CHECK(shatter::test::line_count(r.err) == 1);
    CHECK(r.err.find(words) != std::string::npos);
    CHECK_FALSE(fs::exists(out));
  }
  // Put back whole, the recording is embedded (gzip, base64) beside the grid's results.
  fs::rename(dir / "moved.frames.bin", dir / "grid.frames.bin");
  const auto r = run_cli_argv({"report", grid.string(), "--out", out.string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json data = page_data(out / "report.html");
  CHECK(data["grids"][0]["recorded_frames"].get<std::string>().rfind("H4sI", 0) == 0);  // a gzip header in base64
}
