// Which algorithm a series measured, read from the subjects results_run.cpp writes.

#include "harness/history/series_fracturer.h"

#include <catch2/catch.hpp>

using namespace shatter;

TEST_CASE("series fracturer: the runtime fracturer of a grid cell, the algorithm of a point or row",
          "[history][dashboard]") {
  SeriesKey k;
  k.kind = "grid";
  k.subject = "100 x 25 plane-slice/voronoi/von-mises";
  CHECK(series_fracturer(k) == "voronoi");
  k.subject = "10 x 5 fem-lite/cgal-clip/tresca deferred";
  CHECK(series_fracturer(k) == "cgal-clip");
  k.subject = "10 x 5";
  CHECK(series_fracturer(k).empty());
  k.subject = "10 x 5 no-slashes";
  CHECK(series_fracturer(k).empty());
  k.kind = "accuracy";
  k.subject = "voronoi 32";
  CHECK(series_fracturer(k) == "voronoi");
  k.kind = "table";
  k.subject = "plane-slice 25 fragments";
  CHECK(series_fracturer(k) == "plane-slice");
  k.subject = "";
  CHECK(series_fracturer(k).empty());
}
