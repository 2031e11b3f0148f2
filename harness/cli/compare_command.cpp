#include "harness/cli/command.h"
#include "harness/compare/grid_compare.h"
#include "harness/output/atomic_file.h"
#include "harness/output/output_targets.h"
#include "harness/results/grid_reader.h"
#include "harness/results/junit.h"

#include <fmt/core.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

namespace shatter::cli {
namespace {

struct CompareCommandOptions {
  std::string base;
  std::string next;
  CompareOptions compare;
  std::string junit;
  std::string markdown;
  bool no_normalize = false;
};

int run_compare(const CompareCommandOptions& o) {
  if (Status s = check_compare_options(o.compare); !s) return fail_input(s.error().message);
  if (Status s = check_outputs({{"--markdown", o.markdown}, {"--junit", o.junit}}, baseline_folders(), {o.base, o.next}); !s)
    return fail_input(s.error().message);
  Result<StoredGrid> base = read_grid_results(o.base);
  if (!base) return fail_input(base.error().message);
  Result<StoredGrid> next = read_grid_results(o.next);
  if (!next) return fail_input(next.error().message);

  const CompareReport report = compare_grids(*base, *next, o.compare);
  const std::string markdown = compare_markdown(report, o.compare);
  std::cout << markdown << std::flush;
  if (!o.markdown.empty())
    if (Status s = write_file_atomically(o.markdown, compare_comment_markdown(report, o.compare)); !s)
      return fail_input("--markdown: " + s.error().message);
  if (!o.junit.empty()) {
    JunitSuite suite{"shatterbench.compare." + next->case_name, {}, junit_timestamp(next->context.date),
                     next->context.hostname, {}};
    suite.properties = {{"base", o.base}, {"new", o.next}, {"commit", next->context.commit},
                        {"fingerprint", next->context.fingerprint}};
    for (const std::string& m : report.mismatches) suite.cases.push_back({"comparable results", suite.name, 0.0, m, {}});
    for (const ComparisonRow& r : report.rows) {
      JunitCase c{fmt::format("cell {}: {}", r.cell, r.what), suite.name, 0.0, {}, {}};
      if (r.verdict == Verdict::regressed || r.verdict == Verdict::failed) c.failure = r.note;
      suite.cases.push_back(std::move(c));
    }
    if (Status s = write_file_atomically(o.junit, junit_xml({suite})); !s) return fail_input("--junit: " + s.error().message);
  }
  for (const std::string& w : report.warnings) std::fprintf(stderr, "shatterbench: warning: %s\n", w.c_str());
  if (!report.failed()) return exit_ok;
  for (const std::string& m : report.mismatches) std::fprintf(stderr, "shatterbench: cannot compare: %s\n", m.c_str());
  for (const ComparisonRow& r : report.rows)
    if (r.verdict == Verdict::regressed || r.verdict == Verdict::failed)
      std::fprintf(stderr, "shatterbench: %s: cell %s: %s: %s\n", r.verdict == Verdict::regressed ? "regression" : "accuracy",
                   r.cell.c_str(), r.what.c_str(), r.note.c_str());
  return exit_gate_failed;
}

}  // namespace

void add_compare_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<CompareCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "Compare a grid result against a baseline; exit 1 on a regression (docs/compare.md)");
  cmd->add_option("BASE", o->base, "Baseline results JSON")->required();
  cmd->add_option("NEW", o->next, "New results JSON")->required();
  cmd->add_option("--max-slowdown", o->compare.max_slowdown, "Relative slowdown of a median that can regress (0.05)");
  cmd->add_option("--alpha", o->compare.alpha, "Significance level of the Mann-Whitney U test (0.01)");
  cmd->add_option("--min-change-ms", o->compare.min_change_ms,
                  "Time mode: smaller absolute changes of a median never regress (0.01 ms)");
  cmd->add_option("--metric", o->compare.metric, "time (default) or instructions");
  cmd->add_option("--clock", o->compare.clock, "Time mode: cpu (thread CPU time, default) or wall");
  cmd->add_flag("--no-normalize", o->no_normalize, "CPU clock: do not divide by the calibration workload's time");
  cmd->callback([o, &exit_code] {
    o->compare.normalize = !o->no_normalize;
    exit_code = run_compare(*o);
  });
  cmd->add_option("--junit", o->junit, "Write JUnit XML here: one test case per comparison");
  cmd->add_option("--markdown", o->markdown,
                  "Also write the report as a pull-request comment here: verdict and regressions first, every row "
                  "folded in <details>, at most 65,000 characters");
}

}  // namespace shatter::cli
