// The record of named figures: adding, looking up, and each cell summary rule.

#include "harness/results/figure_record.h"
#include "harness/results/run_figures.h"

#include <catch2/catch.hpp>

namespace {

using namespace shatter;

FigureSpec spec(const char* name, FigureKind kind, CellSummary summary, int cell_order = kFigureLast) {
  FigureSpec s;
  s.name = name;
  s.kind = kind;
  s.summary = summary;
  s.cell_order = cell_order;
  return s;
}

}  // namespace

TEST_CASE("figure record: add keeps order, replaces a name, looks up by name", "[results]") {
  FigureRecord r;
  r.add(spec("a", FigureKind::integer, CellSummary::none), 1);
  r.add(spec("b", FigureKind::number, CellSummary::none), 2.5);
  r.add(spec("a", FigureKind::integer, CellSummary::none), 3);
  REQUIRE(r.figures().size() == 2);
  CHECK(r.figures()[0].spec.name == "a");
  CHECK(r.value("a") == 3);
  r.set("b", 4.5);
  CHECK(r.value("b") == 4.5);
  CHECK(r.find("c") == nullptr);
  CHECK(r.value_or("c", -1.0) == -1.0);
}

TEST_CASE("figure record: a cell summarises each figure by its rule, in cell order", "[results]") {
  std::vector<FigureRecord> samples(3);
  const double values[3] = {5, 1, 3};
  for (int k = 0; k < 3; ++k) {
    samples[k].add(spec("count", FigureKind::integer, CellSummary::median, 2), values[k]);
    samples[k].add(spec("largest", FigureKind::number, CellSummary::max, 1), values[k]);
    samples[k].add(spec("smallest", FigureKind::number, CellSummary::min), values[k]);
    samples[k].add(spec("ok", FigureKind::flag, CellSummary::all), k == 1 ? 0.0 : 1.0);
    samples[k].add(spec("seen", FigureKind::integer, CellSummary::none), values[k]);
  }
  const FigureRecord s = summarise_figures({&samples[0], &samples[1], &samples[2]});
  REQUIRE(s.figures().size() == 4);
  CHECK(s.figures()[0].spec.name == "largest");  // cell_order 1
  CHECK(s.figures()[1].spec.name == "count");    // cell_order 2
  CHECK(s.value("count") == 3);
  CHECK(s.find("count")->spec.kind == FigureKind::number);  // a median is a number
  CHECK(s.value("largest") == 5);
  CHECK(s.value("smallest") == 1);
  CHECK(s.value("ok") == 0.0);
  CHECK(s.find("seen") == nullptr);
  CHECK(summarise_figures({}).empty());
}

TEST_CASE("figure record: a run's figures start at their fallbacks, in sample order", "[results]") {
  const FigureRecord r = run_figure_defaults();
  REQUIRE(r.figures().size() == run_figure_specs().size());
  CHECK(r.figures().front().spec.name == "cache_hit");
  CHECK(r.value("trigger_frame") == -1.0);
  CHECK(r.value("particles_peak") == 0.0);
  CHECK(run_figure_spec("solver.residual").has_value());
  CHECK_FALSE(run_figure_spec("no_such_figure").has_value());
  Figure ms{*run_figure_spec("latency_ms"), 50.0 / 3.0};
  CHECK(figure_text(ms) == "16.666667");
  Figure flag{*run_figure_spec("cache_hit"), 1.0};
  CHECK(figure_text(flag) == "true");
}
