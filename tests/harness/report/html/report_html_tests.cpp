// report_html: the self-contained page, its data element, and a results file that tries to end it.

#include "harness/report/html/report_bundle.h"
#include "harness/report/html/report_html.h"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <string>

namespace {

using namespace shatter;

const std::string kHostile = "</script><script>alert(1)</script>";

/// A grid file's reading with the case name and a cell's fracturer `name`.
ReportInputs hostile_grid(const std::string& name) {
  ReportInputs inputs;
  ReportGrid grid;
  grid.file = "dir/" + name + ".json";
  grid.case_name = name;
  grid.budget_ms = 33.3;
  grid.document = nlohmann::ordered_json::parse(R"({"schema_version": 1, "case": {"name": ""}, "budget_ms": 33.3,
      "cells": [{"prefracture": 10, "runtime": 5, "fracturer": "", "worst_frame_ms": 2.0, "within_budget": true,
                 "stages_ms": {"physics": 1.0}}]})");
  grid.document["case"]["name"] = name;
  grid.document["cells"][0]["fracturer"] = name;
  inputs.grids.push_back(std::move(grid));
  return inputs;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// The text of the data element of `page`.
std::string data_element(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"" + std::string(kReportDataElementId) + "\">";
  const std::size_t start = page.find(open);
  REQUIRE(start != std::string::npos);
  const std::size_t end = page.find("</script>", start);
  REQUIRE(end != std::string::npos);
  return page.substr(start + open.size(), end - start - open.size());
}

}  // namespace

TEST_CASE("report html: a case named </script><script>alert(1)</script> stays data", "[report][html]") {
  const std::string page = report_html(hostile_grid(kHostile));
  // The only elements are the page's own: two script elements, one style element.
  CHECK(count(page, "<script") == 2);
  CHECK(count(page, "</script") == 2);
  CHECK(count(page, "<style") == 1);
  CHECK(page.find("alert(1)</script>") == std::string::npos);
  const std::string data = data_element(page);
  CHECK(data.find('<') == std::string::npos);
  // The element's text is the results as read, under the file's name.
  const nlohmann::json parsed = nlohmann::json::parse(data);
  REQUIRE(parsed.at("grids").size() == 1);
  CHECK(parsed["grids"][0]["file"] == "dir/" + kHostile + ".json");
  CHECK(parsed["grids"][0]["results"]["case"]["name"] == kHostile);
  CHECK(parsed["grids"][0]["results"]["cells"][0]["fracturer"] == kHostile);
  CHECK(parsed["accuracy"].empty());
  CHECK(parsed["stability"].empty());
  CHECK(parsed["tables"].empty());
}

TEST_CASE("report html: one page with its script, style and data inline, loading nothing", "[report][html]") {
  const std::string page = report_html(hostile_grid("building"));
  CHECK(page.rfind("<!doctype html>\n", 0) == 0);
  CHECK(page.find(std::string(report_script())) != std::string::npos);
  CHECK(page.find(std::string(report_style())) != std::string::npos);
  CHECK(page.find("default-src 'none'") != std::string::npos);
  // Nothing of the page names another file or a URL to load.
  for (const char* loads : {"<link", "<img", "<iframe", "<script src", "@import", "url(http", "url(//"}) {
    INFO(loads);
    CHECK(page.find(loads) == std::string::npos);
  }
  // The bundle is the built one, whole: the chunks of the generated source (8,000 bytes each) joined
  // from the IIFE's start to its end; uPlot and the page's own code, and the licence it needs.
  CHECK(report_script().size() > 16000);
  CHECK(report_script().rfind("(()=>{", 0) == 0);
  CHECK(report_script().substr(report_script().size() - 6) == "})();\n");
  CHECK(report_script().find("shatterbench-data") != std::string::npos);
  CHECK(report_style().find(".uplot") != std::string::npos);
  CHECK(report_licenses().find("uplot 1.6.32") != std::string::npos);
  CHECK(report_licenses().find("three 0.187.0") != std::string::npos);
  CHECK(report_licenses().find("MIT License") != std::string::npos);
  // The data element comes before the script that reads it.
  CHECK(page.find(std::string(kReportDataElementId)) < page.find(std::string(report_script())));
}
