// `shatterbench report`: the folder from a small grid and an accuracy run, and malformed input.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

using shatter::test::run_cli;
using shatter::test::slurp;
namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const auto dir = fs::temp_directory_path() / "shatter_report_tests" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// True when `path` is a non-empty PNG (its 8-byte signature) or SVG file.
bool is_image(const fs::path& path) {
  if (!fs::is_regular_file(path) || fs::file_size(path) == 0) return false;
  const std::string bytes = slurp(path);
  if (path.extension() == ".png") return bytes.rfind("\x89PNG\r\n\x1a\n", 0) == 0;
  if (path.extension() == ".svg") return bytes.find("<svg") != std::string::npos;
  return false;
}

int images_in(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    const auto ext = e.path().extension();
    if (ext == ".png" || ext == ".svg") {
      INFO(e.path());
      CHECK(is_image(e.path()));
      ++n;
    }
  }
  return n;
}

}  // namespace

TEST_CASE("cli: report draws the grid heat map, stage bars and time against error", "[cli][report]") {
  const auto dir = scratch("ok");
  const auto grid = dir / "grid.json";
  const auto g = run_cli("grid --case building --prefracture 10,20 --runtime 5 --repetitions 1 --frames 2 --no-cache "
                         "--json " + grid.string());
  INFO(g.err);
  REQUIRE(g.exit_code == 0);
  const auto accuracy = dir / "accuracy.json";
  const auto a = run_cli("accuracy --case cantilever --family stress --model von-mises connection-count --slabs 8 16 "
                         "--repetitions 1 --json " + accuracy.string());
  INFO(a.err);
  REQUIRE(a.exit_code == 0);

  const auto out = dir / "report";
  const auto r = run_cli("report " + grid.string() + " " + accuracy.string() + " --out " + out.string());
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(fs::is_regular_file(out / "report.md"));
  const std::string page = slurp(out / "report.md");
  CHECK(is_image(out / "grid-building.png"));
  CHECK(is_image(out / "stages-building.png"));
  CHECK(is_image(out / "pareto-stress-cantilever.png"));
  CHECK(images_in(out) == 3);
  CHECK(page.find("](grid-building.png)") != std::string::npos);
  CHECK(page.find("](stages-building.png)") != std::string::npos);
  CHECK(page.find("](pareto-stress-cantilever.png)") != std::string::npos);
  CHECK(page.find("### Stages of cell 20 x 5") != std::string::npos);  // the largest cell by default
  // The interactive page beside it, holding both files.
  const std::string html = slurp(out / "report.html");
  CHECK(html.rfind("<!doctype html>", 0) == 0);
  CHECK(html.find("\"file\":\"" + grid.string() + "\"") != std::string::npos);
  CHECK(html.find("\"file\":\"" + accuracy.string() + "\"") != std::string::npos);

  // A chosen cell, and a second run replaces the folder as a whole.
  const auto again = run_cli("report " + grid.string() + " --out " + out.string() + " --cell 10,5");
  REQUIRE(again.exit_code == 0);
  CHECK(slurp(out / "report.md").find("### Stages of cell 10 x 5") != std::string::npos);
  CHECK_FALSE(fs::exists(out / "pareto-stress-cantilever.png"));
  // Nothing is left beside it.
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  CHECK(entries == 4);  // grid.json, grid.csv, accuracy.json, report
}

TEST_CASE("cli: report reads stability and table results, and a hostile case name stays data in report.html",
          "[cli][report]") {
  const auto dir = scratch("kinds");
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  const std::string grid = write("grid.json", R"({"schema_version": 1, "case": {"name": "</script><script>alert(1)</script>"},
      "budget_ms": 5, "cells": [{"prefracture": 1, "runtime": 2, "worst_frame_ms": 1.0, "within_budget": true,
      "stages_ms": {"physics": 1.0}}]})");
  const std::string stability = write("stability.json", R"({"quick": true, "time_limit_s": 60, "results": [
      {"hazard": "thin-plate", "algorithm": "plane-slice", "kind": "fracture", "outcome": "VALID", "detail": "",
       "worst_error": 1e-12, "fragments": 8, "time_ms": 3.5}]})");
  const std::string table = write("table.json", R"({"schema_version": 1, "kind": "table", "repetitions": 1, "rows": [
      {"mesh": "cube.off", "triangles": 12, "algorithm": "voronoi", "fragments": 4, "produced": 4, "time_ms": 0.5,
       "samples_ms": [0.5], "figures": {"volume_error": 0, "all_closed": true}},
      {"mesh": "cube.off", "triangles": 12, "algorithm": "fem-lite", "fragments": 4, "refused": "too thin"}]})");
  const auto out = dir / "report";
  const auto r = shatter::test::run_cli_argv({"report", grid, stability, table, "--out", out.string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("1 grid, 0 accuracy, 1 stability and 1 table file(s)") != std::string::npos);
  const std::string md = slurp(out / "report.md");
  CHECK(md.find("## Stability verdicts") != std::string::npos);
  CHECK(md.find("| thin-plate | plane-slice | fracture | VALID |") != std::string::npos);
  CHECK(md.find("| cube.off | fem-lite | 4 | refused: too thin |  |") != std::string::npos);
  const std::string html = slurp(out / "report.html");
  CHECK(html.find("alert(1)</script>") == std::string::npos);
  CHECK(html.find(R"(\u003c/script\u003e\u003cscript\u003ealert(1)\u003c/script\u003e)") != std::string::npos);
  CHECK(html.find(R"("hazard":"thin-plate")") != std::string::npos);
  CHECK(html.find(R"("kind":"table")") != std::string::npos);
}

TEST_CASE("cli: report refuses malformed JSON with exit 2 naming the file and key, and leaves no folder", "[cli][report]") {
  const auto dir = scratch("bad");
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  const std::string broken = write("broken.json", "{\"cells\": [");
  const std::string no_key = write("nokey.json", R"({"case": {"name": "x"}, "budget_ms": 5, "cells": [{"prefracture": 1, "runtime": 2, "within_budget": true, "stages_ms": {}}]})");
  const std::string wrong = write("wrong.json", R"({"kind": "accuracy", "points": [{"family": "fracture", "case": "a", "algorithm": "b", "knob": "k", "time_ms": "fast", "error": 0, "pareto": true}]})");
  const std::string other = write("other.json", R"({"hello": 1})");
  const std::string newer = write("newer.json", R"({"schema_version": 2, "case": {"name": "x"}, "budget_ms": 5, "cells": []})");
  const std::string bad_row = write("badrow.json", R"({"results": [{"hazard": "h", "algorithm": "a"}]})");
  const auto out = dir / "report";
  const std::pair<std::string, std::string> cases[] = {
      {broken, "broken.json"},
      {no_key, "cells[0].worst_frame_ms"},
      {wrong, "points[0].time_ms"},
      {other, "other.json"},
      {newer, "newer.json: schema_version 2: this shatterbench reads results of version 1"},
      {bad_row, "badrow.json: results[0]"},
      {(dir / "missing.json").string(), "missing.json"},
  };
  for (const auto& [file, words] : cases) {
    INFO(file);
    const auto r = run_cli("report " + file + " --out " + out.string());
    CHECK(r.exit_code == 2);
    CHECK(shatter::test::line_count(r.err) == 1);
    CHECK(r.err.find(words) != std::string::npos);
    CHECK_FALSE(fs::exists(out));
  }
  // A cell the grid does not have is bad input too.
  const auto grid = write("grid.json", R"({"case": {"name": "x"}, "budget_ms": 5, "cells": [{"prefracture": 1, "runtime": 2, "worst_frame_ms": 1.0, "within_budget": true, "stages_ms": {"physics": 1.0}}]})");
  const auto r = run_cli("report " + grid + " --out " + out.string() + " --cell 3,4");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("--cell") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  // No temporary folder is left behind either.
  for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().extension() == ".json");
}
