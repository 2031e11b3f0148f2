// `shatterbench grid`: every sample's per-frame stage times in the results JSON obey the conservation
// laws, the worst frame's breakdown is that frame's column, the cell's is its median repetition's, and
// the Markdown table says what the worst frame is made of.

#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using shatter::test::run_cli;
using shatter::test::slurp;
using Json = nlohmann::json;

/// Allowed excess of a frame's stages over its wall time, ms (the values are whole nanoseconds).
constexpr double kFrameSlackMs = 1e-9;

std::size_t slowest(const Json& frames) {
  std::size_t at = 0;
  for (std::size_t f = 1; f < frames.size(); ++f)
    if (frames[f].get<double>() > frames[at].get<double>()) at = f;
  return at;
}

}  // namespace

TEST_CASE("cli: grid's per-frame stage times add up, and say what the worst frame is made of", "[cli][grid][frame-stages]") {
  const auto dir = std::filesystem::temp_directory_path() / "shatter_grid_tests" / "frame_stages";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto json = dir / "grid.json";
  const auto r = run_cli("grid --case building --prefracture 10,20 --runtime 5 --frames 30 --repetitions 3 "
                         "--no-cache --json " + json.string());
  INFO(r.err);
  REQUIRE((r.exit_code == 0 || r.exit_code == 1));
  REQUIRE(r.out.find("What the worst frame is made of") != std::string::npos);
  REQUIRE(r.out.find("| 10 x 5 |") != std::string::npos);
  const Json j = Json::parse(slurp(json));
  for (const Json& cell : j.at("cells")) {
    for (const Json& s : cell.at("samples")) {
      const Json& frames = s.at("frame_ms");
      const Json& stages = s.at("frame_stages_ms");
      REQUIRE(stages.contains("physics"));
      REQUIRE(stages.contains("runtime_fracture"));
      // Each stage: its frames add up to its total inside frames; a stage that is not written had none.
      for (auto it = s.at("stages_ms").begin(); it != s.at("stages_ms").end(); ++it) {
        const double total = it.value().get<double>();
        if (!stages.contains(it.key())) {
          REQUIRE(total == 0.0);
          continue;
        }
        const Json& column = stages.at(it.key());
        REQUIRE(column.size() == frames.size());
        double sum = 0.0;
        for (const Json& ms : column) sum += ms.get<double>();
        INFO(it.key());
        REQUIRE(std::abs(sum - total) <= 1e-6 * total);
      }
      // Each frame: its stages add up to at most its wall time.
      for (std::size_t f = 0; f < frames.size(); ++f) {
        double sum = 0.0;
        for (auto it = stages.begin(); it != stages.end(); ++it) sum += it.value()[f].get<double>();
        REQUIRE(sum <= frames[f].get<double>() + kFrameSlackMs);
      }
      // The worst frame's breakdown is the slowest frame's column.
      const std::size_t worst = slowest(frames);
      REQUIRE(frames[worst].get<double>() == s.at("worst_frame_ms").get<double>());
      const Json& breakdown = s.at("worst_frame_stages_ms");
      REQUIRE(breakdown.size() == stages.size());
      for (auto it = stages.begin(); it != stages.end(); ++it)
        REQUIRE(breakdown.at(it.key()).get<double>() == it.value()[worst].get<double>());
    }
    // The cell's: the repetition whose worst frame is the median one (3 repetitions: the cell's figure).
    const Json& chosen = cell.at("samples").at(cell.at("worst_frame_repetition").get<std::size_t>());
    REQUIRE(chosen.at("worst_frame_ms").get<double>() == cell.at("worst_frame_ms").get<double>());
    REQUIRE(cell.at("worst_frame_stages_ms") == chosen.at("worst_frame_stages_ms"));
  }
}
