// find_change_points against a published result: the TigerBeetle benchmark series of Apache Otava's
// test suite and the change points Otava reports for it at seven settings
// (tests/fixtures/otava-tigerbeetle-series.json); and against series whose steps are planted.

#include "harness/history/change_points.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <vector>

using namespace shatter;

namespace {

std::vector<std::size_t> indices(const std::vector<SeriesChangePoint>& cps) {
  std::vector<std::size_t> out;
  for (const SeriesChangePoint& cp : cps) out.push_back(cp.index);
  return out;
}

}  // namespace

TEST_CASE("change points: the TigerBeetle series gives Otava's change points at every published setting",
          "[history][change-points]") {
  std::ifstream in(SHATTER_SOURCE_DIR "/tests/fixtures/otava-tigerbeetle-series.json");
  REQUIRE(in.good());
  const nlohmann::json data = nlohmann::json::parse(in);
  const std::vector<double> series = data.at("series").get<std::vector<double>>();
  REQUIRE(series.size() == 365);
  REQUIRE(data.at("expected").size() == 7);
  for (const nlohmann::json& expected : data.at("expected")) {
    ChangePointSettings settings;
    settings.window = expected.at("window_len").get<int>();
    settings.max_pvalue = expected.at("max_pvalue").get<double>();
    settings.min_magnitude = expected.at("min_magnitude").get<double>();
    INFO("window " << settings.window << ", max_pvalue " << settings.max_pvalue << ", min_magnitude "
                   << settings.min_magnitude);
    CHECK(indices(find_change_points(series, settings)) == expected.at("change_points").get<std::vector<std::size_t>>());
  }
}

TEST_CASE("change points: a clean step is found at its first new value, a flat series has none", "[history][change-points]") {
  std::vector<double> series;
  for (int i = 0; i < 60; ++i) series.push_back((i < 37 ? 100.0 : 120.0) + (i % 3) * 0.5);
  const std::vector<SeriesChangePoint> cps = find_change_points(series, {});
  REQUIRE(cps.size() == 1);
  CHECK(cps[0].index == 37);
  CHECK(cps[0].mean_after / cps[0].mean_before == Approx(120.5 / 100.5).epsilon(1e-2));
  CHECK(cps[0].pvalue < 1e-6);
  std::vector<double> flat(60);
  for (int i = 0; i < 60; ++i) flat[static_cast<std::size_t>(i)] = 100.0 + (i % 3) * 0.5;
  CHECK(find_change_points(flat, {}).empty());
}
