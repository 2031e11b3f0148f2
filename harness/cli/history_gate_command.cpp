#include "harness/cli/command.h"
#include "harness/cli/history_access.h"
#include "harness/cli/history_subcommands.h"
#include "harness/compare/grid_compare.h"
#include "harness/history/calibration_scaling.h"
#include "harness/history/history_gate.h"
#include "harness/output/atomic_file.h"
#include "harness/output/output_targets.h"
#include "harness/results/junit.h"
#include "harness/results/markdown_text.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <tuple>
#include <memory>
#include <string>

namespace shatter::cli {
namespace {

struct GateOptions {
  StoreFlags store;
  SeriesFilter filter;
  std::string commit;
  std::string repo;
  std::string markdown;
  std::string junit;
  std::string baseline_branch;
  HistoryGateSettings settings;
};

struct GateRow {
  SeriesInfo series;
  SeriesVerdict verdict;
};

std::string row_text(const GateRow& r) {
  const SeriesVerdict& v = r.verdict;
  return fmt::format("| {} | {:.6g} | {:.6g} | {:+.2f} % | {} | {} | {} | {} |\n", markdown_cell(series_label(r.series.key)),
                     v.base_median, v.new_median, 100.0 * v.change, v.pvalue < 0 ? std::string("-") : fmt::format("{:.2g}", v.pvalue),
                     v.baseline_size, v.verdict == GateVerdict::regressed ? "**regressed**" : gate_verdict_name(v.verdict),
                     markdown_cell(v.note));
}

constexpr const char* kTableHead =
    "| series | baseline median | new median | change | p-value | baseline commits | verdict | note |\n"
    "|---|---:|---:|---:|---:|---:|---|---|\n";

/// The page: verdict line, failed runs, regressions, improvements, then (folded when `folded`) every
/// row; at most `max_chars` (rows that do not fit are counted).
std::string gate_markdown(const std::string& headline, const std::vector<std::string>& failed_runs,
                          const std::vector<GateRow>& rows, bool folded, std::size_t max_chars) {
  std::string out = headline + "\n\n";
  for (const std::string& f : failed_runs) out += "- " + markdown_cell(f) + "\n";
  if (!failed_runs.empty()) out += "\n";
  std::size_t left_out = 0;
  auto section = [&](const char* title, auto keep) {
    std::string body;
    for (const GateRow& r : rows)
      if (keep(r)) {
        const std::string line = row_text(r);
        if (out.size() + body.size() + line.size() + 200 > max_chars) ++left_out;
        else body += line;
      }
    if (!body.empty()) out += fmt::format("### {}\n\n{}{}\n", title, kTableHead, body);
  };
  section("Regressions", [](const GateRow& r) { return r.verdict.verdict == GateVerdict::regressed; });
  section("Improvements", [](const GateRow& r) { return r.verdict.verdict == GateVerdict::improved; });
  if (folded) out += fmt::format("<details><summary>All {} series</summary>\n\n", rows.size());
  section("All series", [](const GateRow&) { return true; });
  if (folded) out += "</details>\n";
  if (left_out > 0) out += fmt::format("\n{} rows left out (the comment's size limit)\n", left_out);
  return out;
}

int run_gate(const GateOptions& o) {
  if (Status s = check_history_gate_settings(o.settings); !s) return fail_input(s.error().message);
  if (Status s = check_outputs({{"--markdown", o.markdown}, {"--junit", o.junit}}); !s) return fail_input(s.error().message);
  Result<HistoryStore> store = open_store(o.store, false);
  if (!store) return fail_input(store.error().message);
  Result<CommitInfo> commit = recorded_commit(*store, o.commit, o.repo);
  if (!commit) return fail_input("--commit: " + commit.error().message);
  Result<std::vector<RunSummary>> runs = store->runs_at(commit->sha);
  if (!runs) return fail_input(runs.error().message);

  std::vector<std::string> failed_runs;
  for (const RunSummary& r : *runs)
    if (!r.passed && (o.filter.case_name.empty() || r.case_name == o.filter.case_name))
      failed_runs.push_back(fmt::format("run {} ({} {}) failed its own checks: a budget or a result check", r.source, r.kind, r.case_name));

  auto all = store->filtered_series_runs(o.filter);
  if (!all) return fail_input(all.error().message);
  // Each grid cell's calibration samples, for its CPU times (calibration_scaling.h).
  SeriesFilter calibration_filter = o.filter;
  calibration_filter.kind = "grid";
  calibration_filter.what = "calibration";
  calibration_filter.metric = "cpu_ms";
  auto calibrations = store->filtered_series_runs(calibration_filter);
  if (!calibrations) return fail_input(calibrations.error().message);
  std::map<std::string, RunCalibrations> calibration_of;  // by case, fingerprint and subject
  auto cell_key = [](const SeriesKey& k) { return k.case_name + '\x1f' + k.fingerprint + '\x1f' + k.subject; };
  for (const auto& [info, calibration_runs] : *calibrations)
    for (const SeriesRun& run : calibration_runs) calibration_of[cell_key(info.key)][run.run_id] = run.samples;
  Result<std::vector<Acknowledgement>> acks = store->all_acknowledgements();
  if (!acks) return fail_input(acks.error().message);
  std::multimap<std::int64_t, Acknowledgement> acks_of;
  for (Acknowledgement& a : *acks) acks_of.emplace(a.series_id, std::move(a));
  std::vector<GateRow> rows;
  for (auto& [info, series_runs] : *all) {
    if (info.key.better == Better::none) continue;
    // A grid's wall-clock times (stages, frames, figures in ms) are judged through their CPU times,
    // calibrated, unless asked for by name: a shared machine moves them by more than a gate can bear.
    if (o.filter.metric.empty() && info.key.kind == "grid" && info.key.unit == "ms" && info.key.metric != "cpu_ms")
      continue;
    // The judged runs: up to the gated commit; of the baseline branch (the gated commit's own always);
    // none made from a working tree with changes but the gated commit's.
    const auto last = std::find_if(series_runs.rbegin(), series_runs.rend(),
                                   [&](const SeriesRun& r) { return r.commit == commit->sha; });
    if (last == series_runs.rend()) continue;  // the gated commit did not measure this series
    series_runs.erase(last.base(), series_runs.end());
    std::erase_if(series_runs, [&](const SeriesRun& r) {
      if (r.commit == commit->sha) return false;
      return r.dirty || (!o.baseline_branch.empty() && r.branch != o.baseline_branch);
    });
    // CPU times per calibration, scaled by the judged runs' own median calibration.
    bool normalized = false;
    if (info.key.kind == "grid" && info.key.metric == "cpu_ms" && info.key.what != "calibration")
      if (const auto c = calibration_of.find(cell_key(info.key)); c != calibration_of.end())
        normalized = normalize_by_calibration(series_runs, c->second);
    const std::vector<CommitPoint> points = commit_points(series_runs);
    // Judged from the latest acknowledgement on: the first point at or after its commit.
    std::size_t first = 0;
    for (auto a = acks_of.lower_bound(info.id); a != acks_of.end() && a->first == info.id; ++a)
      for (std::size_t i = 0; i < points.size(); ++i)
        if (std::make_tuple(points[i].time, points[i].generation, points[i].commit) >=
            std::make_tuple(a->second.commit_time, a->second.generation, a->second.commit)) {
          first = std::max(first, i);
          break;
        }
    rows.push_back(GateRow{info, judge_newest(points, first, info.key.better, info.key.unit, o.settings)});
    if (normalized) rows.back().verdict.note = "per calibration" + (rows.back().verdict.note.empty() ? "" : "; " + rows.back().verdict.note);
  }
  if (rows.empty() && failed_runs.empty())
    return fail_input(fmt::format("--commit {}: no series of the filter measured at {} in {}", o.commit,
                                  commit->sha.substr(0, 12), store->name()));
  std::stable_sort(rows.begin(), rows.end(), [](const GateRow& a, const GateRow& b) {
    auto rank = [](GateVerdict v) { return v == GateVerdict::regressed ? 0 : v == GateVerdict::improved ? 1 : 2; };
    return rank(a.verdict.verdict) < rank(b.verdict.verdict);
  });
  const auto regressed = static_cast<std::size_t>(std::count_if(
      rows.begin(), rows.end(), [](const GateRow& r) { return r.verdict.verdict == GateVerdict::regressed; }));
  const auto improved = static_cast<std::size_t>(std::count_if(
      rows.begin(), rows.end(), [](const GateRow& r) { return r.verdict.verdict == GateVerdict::improved; }));
  const bool failed = regressed > 0 || !failed_runs.empty();
  const std::string headline = fmt::format(
      "**shatterbench history gate: {}** at {}: {} regressed, {} improved and {} failed run(s) in {} series "
      "(threshold {:g} %, alpha {:g}, recent {}; {})",
      failed ? "FAILED" : "passed", commit->sha.substr(0, 12), regressed, improved, failed_runs.size(), rows.size(),
      100.0 * o.settings.threshold, o.settings.alpha, o.settings.recent, store->name());
  std::cout << gate_markdown(headline, failed_runs, rows, false, std::string::npos / 2) << std::flush;
  if (!o.markdown.empty())
    if (Status s = write_file_atomically(o.markdown, gate_markdown(headline, failed_runs, rows, true, kCommentChars)); !s)
      return fail_input("--markdown: " + s.error().message);
  if (!o.junit.empty()) {
    JunitSuite suite{"shatterbench.history", {}, {}, {}, {}};
    suite.properties = {{"commit", commit->sha}, {"store", store->name()}};
    for (const std::string& f : failed_runs) suite.cases.push_back({"run checks", suite.name, 0.0, f, "check", {}, {}});
    for (const GateRow& r : rows) {
      JunitCase c{series_label(r.series.key), suite.name, 0.0, {}, {}, {}, {}};
      if (r.verdict.verdict == GateVerdict::regressed) {
        c.failure = fmt::format("regressed {:+.2f} % ({}) against {} commits{}", 100.0 * r.verdict.change,
                                r.verdict.pvalue < 0 ? std::string("by the thresholds") : fmt::format("p {:.2g}", r.verdict.pvalue),
                                r.verdict.baseline_size, r.verdict.note.empty() ? "" : "; " + r.verdict.note);
        c.failure_type = "regression";
      }
      c.properties = {{"baseline_median", fmt::format("{:g}", r.verdict.base_median)},
                      {"new_median", fmt::format("{:g}", r.verdict.new_median)}};
      suite.cases.push_back(std::move(c));
    }
    if (Status s = write_file_atomically(o.junit, junit_xml({suite})); !s) return fail_input("--junit: " + s.error().message);
  }
  if (!failed) return exit_ok;
  for (const std::string& f : failed_runs) std::fprintf(stderr, "shatterbench: %s\n", f.c_str());
  for (const GateRow& r : rows)
    if (r.verdict.verdict == GateVerdict::regressed)
      std::fprintf(stderr, "shatterbench: regression: %s: %+.2f %%\n", series_label(r.series.key).c_str(), 100.0 * r.verdict.change);
  return exit_gate_failed;
}

struct AckOptions {
  StoreFlags store;
  SeriesFilter filter;
  std::string commit;
  std::string repo;
  std::string note;
  bool all = false;
};

int run_ack(const AckOptions& o) {
  const SeriesFilter& f = o.filter;
  if (!o.all && f.case_name.empty() && f.kind.empty() && f.subject.empty() && f.what.empty() && f.metric.empty() &&
      f.fingerprint.empty())
    return fail_input("ack: name the series (--case, --subject, --what, --metric, ...) or give --all");
  Result<HistoryStore> store = open_store(o.store, false);
  if (!store) return fail_input(store.error().message);
  Result<CommitInfo> commit = recorded_commit(*store, o.commit, o.repo);
  if (!commit) return fail_input("--commit: " + commit.error().message);
  Result<std::vector<SeriesInfo>> series = store->list_series(f);
  if (!series) return fail_input(series.error().message);
  if (series->empty()) return fail_input("ack: no series matches");
  for (const SeriesInfo& s : *series)
    if (Status st = store->acknowledge({s.id, commit->sha, o.note, {}}); !st) return fail_input(st.error().message);
  std::cout << fmt::format("acknowledged {} series at {}: the gate judges them from that commit on\n", series->size(),
                           commit->sha.substr(0, 12));
  return exit_ok;
}

}  // namespace

void add_history_gate_commands(CLI::App& history, int& exit_code) {
  auto o = std::make_shared<GateOptions>();
  CLI::App* gate = history.add_subcommand(
      "gate", "Exit 1 when a commit's runs regress against their series' last stable segment (docs/history.md)");
  gate->add_option("--commit", o->commit, "The commit to judge (a recorded sha prefix or a git revision, e.g. HEAD)")->required();
  add_store_flags(gate, o->store);
  add_series_filter_flags(gate, o->filter);
  gate->add_option("--repo", o->repo, "The git repository that resolves --commit (default: the working folder)");
  gate->add_option("--baseline-branch", o->baseline_branch,
                   "Judge against the commits of this branch only (e.g. main; default: every recorded commit)");
  gate->add_option("--markdown", o->markdown, "Write the pull-request comment here (at most 65,000 characters)");
  gate->add_option("--junit", o->junit, "Write JUnit XML here: one test case per series");
  HistoryGateSettings& s = o->settings;
  gate->add_option("--threshold", s.threshold, "Smallest relative change that regresses")->capture_default_str();
  gate->add_option("--alpha", s.alpha, "Significance level of the U test of the newest samples")->capture_default_str();
  gate->add_option("--recent", s.recent, "A step among this many newest commits is judged against the segment before it")
      ->capture_default_str();
  gate->add_option("--baseline-commits", s.baseline_commits, "Most commits in the baseline")->capture_default_str();
  gate->add_option("--min-change-ms", s.min_change_ms, "Series in ms: smaller absolute changes never regress")->capture_default_str();
  gate->add_option("--test", s.test, "samples (U test on every sample), medians (prediction test on the commit medians) or robust (the same, median and MAD)")
      ->capture_default_str();
  gate->add_option("--window", s.change_points.window, "Change points: points per window")->capture_default_str();
  gate->add_option("--max-pvalue", s.change_points.max_pvalue, "Change points: largest p-value")->capture_default_str();
  gate->callback([o, &exit_code] { exit_code = run_gate(*o); });

  auto a = std::make_shared<AckOptions>();
  CLI::App* ack = history.add_subcommand("ack", "Accept the series' level at a commit: the gate judges them from it on");
  ack->add_option("--commit", a->commit, "The commit whose change is expected")->required();
  ack->add_option("--note", a->note, "Why (kept with the acknowledgement)")->required();
  ack->add_flag("--all", a->all, "Every series (else at least one filter)");
  add_store_flags(ack, a->store);
  add_series_filter_flags(ack, a->filter);
  ack->add_option("--repo", a->repo, "The git repository that resolves --commit (default: the working folder)");
  ack->callback([a, &exit_code] { exit_code = run_ack(*a); });
}

}  // namespace shatter::cli
