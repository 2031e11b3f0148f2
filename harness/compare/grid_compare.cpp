#include "harness/compare/grid_compare.h"

#include "harness/compare/mann_whitney.h"
#include "harness/results/sample_statistics.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace shatter {
namespace {

std::string cell_name(const GridCell& c) { return fmt::format("{} x {}", c.prefracture, c.runtime); }

std::string cell_key(const GridCell& c) {
  return fmt::format("{}|{}|{}|{}|{}", c.prefracture, c.runtime, c.prefracturer, c.fracturer, c.stress);
}

double p99_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return quantile_of_sorted(v, 0.99);
}

/// new / base - 1, or nothing when it is undefined: a base of 0 (a stage that took no time, or no
/// instructions), a negative base, or a base so small that the ratio overflows.
std::optional<double> relative_change(double base, double next) {
  if (!(base > 0.0)) return std::nullopt;
  const double change = next / base - 1.0;
  if (!std::isfinite(change)) return std::nullopt;
  return change;
}

/// The Markdown of a row's change: a percentage, or the absolute change with its unit when the
/// relative one is undefined.
std::string change_text(const ComparisonRow& r, bool time) {
  if (r.change_defined) return fmt::format("{:+.1f} %", 100 * r.change);
  const double delta = r.new_median - r.base_median;
  if (!std::isfinite(delta)) return "n/a";
  return time ? fmt::format("{:+.3f} ms", delta) : fmt::format("{:+.0f} instr.", delta);
}

/// One timed or counted row from per-repetition samples.
ComparisonRow measure_row(const std::string& cell, const std::string& what, const std::vector<double>& base,
                          const std::vector<double>& next, const std::vector<double>& base_p99_set,
                          const std::vector<double>& next_p99_set, const CompareOptions& o) {
  ComparisonRow r;
  r.cell = cell;
  r.what = what;
  r.base_median = median_of(base);
  r.new_median = median_of(next);
  const std::optional<double> change = relative_change(r.base_median, r.new_median);
  r.change_defined = change.has_value();
  r.change = change.value_or(0.0);
  r.base_p99 = p99_of(base_p99_set);
  r.new_p99 = p99_of(next_p99_set);
  const double delta = r.new_median - r.base_median;
  if (!r.change_defined) {
    // No relative change: the absolute change decides, against --min-change-ms in time mode (with the
    // U test as ever), and any increase of a count in instruction mode. A zero base hides nothing.
    const bool time = o.metric == "time";
    const MannWhitneyResult test = time ? mann_whitney_u(base, next) : MannWhitneyResult{};
    if (time) r.p_value = test.p_value;
    const bool large = time ? std::abs(delta) >= o.min_change_ms && delta != 0.0 : delta != 0.0;
    const bool significant = !time || test.p_value < o.alpha;
    const std::string absolute = time ? fmt::format("{:+.3f} ms from a base of {:.3g} ms", delta, r.base_median)
                                  : fmt::format("{:+.0f} instructions from a base of {:.0f}", delta, r.base_median);
    if (large && significant) {
      r.verdict = delta > 0.0 ? Verdict::regressed : Verdict::improved;
      r.note = time ? fmt::format("median {} (no relative change), >= {:g} ms and p = {:.2g} < {:g}", absolute,
                                  o.min_change_ms, test.p_value, o.alpha)
                    : fmt::format("{} (no relative change)", absolute);
    } else if (large && delta > 0.0) {
      r.note = fmt::format("slower by {} but p = {:.2g} >= {:g}: not shown to be more than noise", absolute,
                           test.p_value, o.alpha);
    } else if (delta > 0.0) {
      r.note = fmt::format("slower by {}, less than {:g} ms", absolute, o.min_change_ms);
    }
    return r;
  }
  if (o.metric == "time") {
    const MannWhitneyResult test = mann_whitney_u(base, next);
    r.p_value = test.p_value;
    const bool significant = test.p_value < o.alpha && std::abs(delta) >= o.min_change_ms;
    if (r.change > o.max_slowdown && significant) {
      r.verdict = Verdict::regressed;
      r.note = fmt::format("median +{:.1f} % > {:.1f} % and p = {:.2g} < {:g}", 100 * r.change, 100 * o.max_slowdown,
                           test.p_value, o.alpha);
    } else if (r.change < -o.max_slowdown && significant) {
      r.verdict = Verdict::improved;
      r.note = fmt::format("median {:.1f} %, p = {:.2g}", 100 * r.change, test.p_value);
    } else if (r.change > o.max_slowdown && test.p_value < o.alpha) {
      r.note = fmt::format("slower by {:.1f} %, p = {:.2g}, but by less than {:g} ms", 100 * r.change, test.p_value,
                           o.min_change_ms);
    } else if (r.change > o.max_slowdown) {
      r.note = fmt::format("slower by {:.1f} % but p = {:.2g} >= {:g}: not shown to be more than noise",
                           100 * r.change, test.p_value, o.alpha);
    }
  } else {
    if (r.change > o.max_slowdown) {
      r.verdict = Verdict::regressed;
      r.note = fmt::format("+{:.2f} % instructions > {:.1f} %", 100 * r.change, 100 * o.max_slowdown);
    } else if (r.change < -o.max_slowdown) {
      r.verdict = Verdict::improved;
      r.note = fmt::format("{:.2f} % instructions", 100 * r.change);
    }
  }
  return r;
}

ComparisonRow accuracy_row(const GridCell& base, const GridCell& next, const AccuracyTolerances& t) {
  ComparisonRow r;
  r.cell = cell_name(base);
  r.what = "accuracy";
  std::vector<std::string> failed;
  const CellAccuracy& b = base.accuracy;
  const CellAccuracy& n = next.accuracy;
  if (n.prefracture_volume_error > b.prefracture_volume_error + t.volume_error)
    failed.push_back(fmt::format("pre-fracture volume error {:.3g} -> {:.3g}", b.prefracture_volume_error,
                                 n.prefracture_volume_error));
  if (n.runtime_volume_error > b.runtime_volume_error + t.volume_error)
    failed.push_back(fmt::format("runtime volume error {:.3g} -> {:.3g}", b.runtime_volume_error, n.runtime_volume_error));
  if (n.prefracture_partition_error > b.prefracture_partition_error + t.partition_error)
    failed.push_back(fmt::format("pre-fracture partition error {:.3g} -> {:.3g}", b.prefracture_partition_error,
                                 n.prefracture_partition_error));
  if (n.runtime_partition_error > b.runtime_partition_error + t.partition_error)
    failed.push_back(fmt::format("runtime partition error {:.3g} -> {:.3g}", b.runtime_partition_error,
                                 n.runtime_partition_error));
  if (b.prefracture_all_closed && !n.prefracture_all_closed) failed.emplace_back("a pre-fracture fragment is not closed");
  if (b.runtime_all_closed && !n.runtime_all_closed) failed.emplace_back("a runtime piece is not closed");
  if (b.solver_converged && !n.solver_converged) failed.emplace_back("a stress solve did not converge");
  r.base_median = std::max(b.prefracture_volume_error, b.runtime_volume_error);
  r.new_median = std::max(n.prefracture_volume_error, n.runtime_volume_error);
  if (!failed.empty()) {
    r.verdict = Verdict::failed;
    for (std::size_t i = 0; i < failed.size(); ++i) r.note += (i ? "; " : "") + failed[i];
  }
  return r;
}

std::vector<double> per_rep(const GridCell& c, double GridSample::*field) {
  std::vector<double> v;
  for (const GridSample& s : c.samples) v.push_back(s.*field);
  return v;
}

bool has_instructions(const GridCell& c) {
  return std::all_of(c.samples.begin(), c.samples.end(), [](const GridSample& s) { return s.instructions.has_value(); });
}

}  // namespace

bool CompareReport::failed() const {
  if (!mismatches.empty()) return true;
  return std::any_of(rows.begin(), rows.end(),
                     [](const ComparisonRow& r) { return r.verdict == Verdict::regressed || r.verdict == Verdict::failed; });
}

Status check_compare_options(const CompareOptions& o) {
  if (!std::isfinite(o.max_slowdown) || o.max_slowdown <= 0.0)
    return Error{fmt::format("--max-slowdown: must be a finite number > 0, got {}", o.max_slowdown)};
  if (!std::isfinite(o.alpha) || o.alpha <= 0.0 || o.alpha >= 1.0)
    return Error{fmt::format("--alpha: must be in (0, 1), got {}", o.alpha)};
  if (o.metric != "time" && o.metric != "instructions")
    return Error{"--metric: must be time or instructions, got \"" + o.metric + "\""};
  if (!std::isfinite(o.min_change_ms) || o.min_change_ms < 0.0)
    return Error{fmt::format("--min-change-ms: must be a finite number >= 0, got {}", o.min_change_ms)};
  if (o.clock != "cpu" && o.clock != "wall") return Error{"--clock: must be cpu or wall, got \"" + o.clock + "\""};
  return {};
}

CompareReport compare_grids(const StoredGrid& base, const StoredGrid& next, const CompareOptions& o,
                            const AccuracyTolerances& t) {
  CompareReport out;
  out.metric = o.metric;
  if (base.context.fingerprint != next.context.fingerprint)
    out.mismatches.push_back(fmt::format(
        "build fingerprints differ ({} in {}, {} in {}): the two results were measured with different "
        "compilers, flags, libraries or CPUs and cannot be compared",
        base.context.fingerprint, base.path.string(), next.context.fingerprint, next.path.string()));
  if (base.case_block != next.case_block)
    out.mismatches.push_back(fmt::format("the cases differ ({} in {}, {} in {}, or their settings)", base.case_name,
                                         base.path.string(), next.case_name, next.path.string()));
  if (base.grid.frames != next.grid.frames)
    out.mismatches.push_back(fmt::format("frames per run differ: {} against {}", base.grid.frames, next.grid.frames));

  std::map<std::string, const GridCell*> new_cells;
  for (const GridCell& c : next.grid.cells) new_cells[cell_key(c)] = &c;

  const int base_reps = base.grid.repetitions, new_reps = next.grid.repetitions;
  if (o.metric == "time" && smallest_p_value(base_reps, new_reps) >= o.alpha)
    out.warnings.push_back(fmt::format(
        "{} and {} repetitions: the smallest p-value the U test can give is {:.2g}, not below alpha {:g}, so no "
        "timing regression can be shown; use 9 or more repetitions",
        base_reps, new_reps, smallest_p_value(base_reps, new_reps), o.alpha));
  else if (o.metric == "time" && (base_reps < 9 || new_reps < 9))
    out.warnings.push_back(fmt::format("fewer than 9 repetitions ({} and {}): the U test has little power",
                                       base_reps, new_reps));

  if (o.metric == "time" && o.clock == "cpu") {
    std::vector<double> bc, nc;
    bool all = true;
    for (const GridCell& c : base.grid.cells)
      for (const GridSample& s : c.samples) {
        bc.push_back(s.calibration_ms);
        all = all && s.calibration_ms > 0.0;
      }
    for (const GridCell& c : next.grid.cells)
      for (const GridSample& s : c.samples) {
        nc.push_back(s.calibration_ms);
        all = all && s.calibration_ms > 0.0;
      }
    out.base_calibration_ms = median_of(bc);
    out.new_calibration_ms = median_of(nc);
    out.normalized = o.normalize && all && !bc.empty() && !nc.empty();
    // A calibration time so small that the scale overflows would make every time Inf: not normalized.
    for (const double c : bc) out.normalized = out.normalized && std::isfinite(out.base_calibration_ms / c);
    for (const double c : nc) out.normalized = out.normalized && std::isfinite(out.base_calibration_ms / c);
  }
  if (o.metric == "time" && (!base.grid.same_seed || !next.grid.same_seed))
    out.warnings.push_back(
        "repetitions with different seeds fracture differently, so their spread is workload, not noise, and the U "
        "test loses its power; measure gates with grid --same-seed");
  for (const GridCell& b : base.grid.cells) {
    const auto it = new_cells.find(cell_key(b));
    if (it == new_cells.end()) {
      out.mismatches.push_back(fmt::format("cell {} ({}, {}, {}) of {} is missing from {}", cell_name(b), b.prefracturer,
                                           b.fracturer, b.stress, base.path.string(), next.path.string()));
      continue;
    }
    const GridCell& n = *it->second;
    const std::string name = cell_name(b);
    if (!b.failed.empty() || !n.failed.empty()) {  // a timed-out or crashed cell has nothing to compare
      out.mismatches.push_back(fmt::format("cell {} failed in {}: {}", name,
                                           (!b.failed.empty() ? base : next).path.string(),
                                           !b.failed.empty() ? b.failed : n.failed));
      continue;
    }
    if (o.metric == "instructions") {
      if (!has_instructions(b) || !has_instructions(n)) {
        out.mismatches.push_back(fmt::format("cell {}: no instruction counts (run grid --metric instructions)", name));
        continue;
      }
      std::vector<double> bw, nw, bf, nf;
      for (const GridSample& s : b.samples) {
        bw.push_back(s.instructions->worst_frame);
        bf.insert(bf.end(), s.instructions->frames.begin(), s.instructions->frames.end());
      }
      for (const GridSample& s : n.samples) {
        nw.push_back(s.instructions->worst_frame);
        nf.insert(nf.end(), s.instructions->frames.begin(), s.instructions->frames.end());
      }
      out.rows.push_back(measure_row(name, "worst frame", bw, nw, bf, nf, o));
      for (const Stage st : kAllStages) {
        std::vector<double> bs, ns;
        for (const GridSample& s : b.samples) bs.push_back(s.instructions->stages[static_cast<std::size_t>(st)]);
        for (const GridSample& s : n.samples) ns.push_back(s.instructions->stages[static_cast<std::size_t>(st)]);
        if (median_of(bs) == 0.0 && median_of(ns) == 0.0) continue;
        out.rows.push_back(measure_row(name, "stage " + std::string(stage_name(st)), bs, ns, bs, ns, o));
      }
    } else if (o.clock == "cpu") {
      // Per repetition: the CPU time, divided by the calibration of that repetition when normalizing
      // and scaled back to the baseline's machine speed.
      const auto scale = [&](const GridSample& s) {
        return out.normalized ? out.base_calibration_ms / s.calibration_ms : 1.0;
      };
      std::vector<double> bw, nw;
      for (const GridSample& s : b.samples) bw.push_back(s.worst_frame_cpu_ms * scale(s));
      for (const GridSample& s : n.samples) nw.push_back(s.worst_frame_cpu_ms * scale(s));
      const std::string tag = out.normalized ? " (cpu, normalized)" : " (cpu)";
      out.rows.push_back(measure_row(name, "worst frame" + tag, bw, nw, bw, nw, o));
      for (const Stage st : kAllStages) {
        std::vector<double> bs, ns;
        for (const GridSample& s : b.samples) bs.push_back(s.stages_cpu_ms[static_cast<std::size_t>(st)] * scale(s));
        for (const GridSample& s : n.samples) ns.push_back(s.stages_cpu_ms[static_cast<std::size_t>(st)] * scale(s));
        if (median_of(bs) == 0.0 && median_of(ns) == 0.0) continue;
        out.rows.push_back(measure_row(name, "stage " + std::string(stage_name(st)) + tag, bs, ns, bs, ns, o));
      }
    } else {
      std::vector<double> bf, nf;
      for (const GridSample& s : b.samples) bf.insert(bf.end(), s.frame_ms.begin(), s.frame_ms.end());
      for (const GridSample& s : n.samples) nf.insert(nf.end(), s.frame_ms.begin(), s.frame_ms.end());
      out.rows.push_back(measure_row(name, "worst frame", per_rep(b, &GridSample::worst_frame_ms),
                                     per_rep(n, &GridSample::worst_frame_ms), bf, nf, o));
      for (const Stage st : kAllStages) {
        std::vector<double> bs, ns;
        for (const GridSample& s : b.samples) bs.push_back(s.stages_ms[static_cast<std::size_t>(st)]);
        for (const GridSample& s : n.samples) ns.push_back(s.stages_ms[static_cast<std::size_t>(st)]);
        if (median_of(bs) == 0.0 && median_of(ns) == 0.0) continue;
        out.rows.push_back(measure_row(name, "stage " + std::string(stage_name(st)), bs, ns, bs, ns, o));
      }
    }
    out.rows.push_back(accuracy_row(b, n, t));
  }
  return out;
}

namespace {

/// The table's header for `time` (ms) or instruction counts.
std::string table_header(bool time) {
  const char* unit = time ? "ms" : "instr.";
  return fmt::format("| cell | what | base median {0} | new median {0} | change | base p99 {0} | new p99 {0} | p | "
                     "verdict |\n|---|---|---:|---:|---:|---:|---:|---:|---|\n",
                     unit);
}

/// One row of the table.
std::string table_row(const ComparisonRow& r, bool time) {
  // Figures are finite (the reader refuses Inf); a difference of two huge ones may still overflow.
  const auto value = [&](double v) {
    if (!std::isfinite(v)) return std::string("n/a");
    return time ? fmt::format("{:.3f}", v) : fmt::format("{:.0f}", v);
  };
  const char* verdict = r.verdict == Verdict::regressed ? "**regressed**"
                        : r.verdict == Verdict::failed  ? "**failed**"
                        : r.verdict == Verdict::improved ? "improved"
                                                         : "same";
  if (r.what == "accuracy")
    return fmt::format("| {} | accuracy | {:.2g} | {:.2g} | | | | | {}{} |\n", r.cell, r.base_median, r.new_median,
                       verdict, r.note.empty() ? "" : ": " + r.note);
  return fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {}{} |\n", r.cell, r.what, value(r.base_median),
                     value(r.new_median), change_text(r, time), value(r.base_p99), value(r.new_p99),
                     r.p_value < 0 ? std::string("n/a") : fmt::format("{:.2g}", r.p_value), verdict,
                     r.note.empty() ? "" : ": " + r.note);
}

bool is_bad(const ComparisonRow& r) { return r.verdict == Verdict::regressed || r.verdict == Verdict::failed; }

/// The rows, failures and regressions first, then improvements, then the rest, each in report order.
std::vector<const ComparisonRow*> ranked_rows(const CompareReport& report) {
  const auto rank = [](Verdict v) {
    switch (v) {
      case Verdict::failed: return 0;
      case Verdict::regressed: return 1;
      case Verdict::improved: return 2;
      case Verdict::same: return 3;
    }
    return 3;
  };
  std::vector<const ComparisonRow*> rows;
  for (const ComparisonRow& r : report.rows) rows.push_back(&r);
  std::stable_sort(rows.begin(), rows.end(), [&](const auto* a, const auto* b) { return rank(a->verdict) < rank(b->verdict); });
  return rows;
}

/// Mismatches, warnings, the calibration and the verdict line.
std::string compare_preamble(const CompareReport& report, const CompareOptions& o) {
  std::string out;
  int regressed = 0, failed = 0, improved = 0;
  for (const ComparisonRow& r : report.rows) {
    regressed += r.verdict == Verdict::regressed;
    failed += r.verdict == Verdict::failed;
    improved += r.verdict == Verdict::improved;
  }
  const bool time = report.metric == "time";
  out += fmt::format("**{}**: {} regressed, {} accuracy failures, {} improved, {} rows; metric {}, max slowdown "
                     "{:g} %{}\n\n",
                     report.failed() ? "FAIL" : "PASS", regressed, failed, improved, report.rows.size(), report.metric,
                     100 * o.max_slowdown,
                     time ? fmt::format(", alpha {:g}, {} clock", o.alpha, o.clock) : std::string());
  if (!report.mismatches.empty()) {
    out += "**Cannot compare:**\n\n";
    for (const std::string& m : report.mismatches) out += "- " + m + "\n";
    out += "\n";
  }
  for (const std::string& w : report.warnings) out += "> warning: " + w + "\n\n";
  if (report.base_calibration_ms > 0.0 && report.new_calibration_ms > 0.0 &&
      std::isfinite(report.new_calibration_ms / report.base_calibration_ms))
    out += fmt::format("Calibration workload: {:.3f} ms (base) and {:.3f} ms (new): the new run's machine was {:+.1f} % "
                       "slower{}\n\n",
                       report.base_calibration_ms, report.new_calibration_ms,
                       100 * (report.new_calibration_ms / report.base_calibration_ms - 1.0),
                       report.normalized ? "; CPU times are normalized by it" : "; not normalized");
  return out;
}

}  // namespace

std::string compare_markdown(const CompareReport& report, const CompareOptions& o) {
  const bool time = report.metric == "time";
  std::string out = compare_preamble(report, o) + table_header(time);
  for (const ComparisonRow* r : ranked_rows(report)) out += table_row(*r, time);
  return out;
}

std::string compare_comment_markdown(const CompareReport& report, const CompareOptions& o, std::size_t max_chars) {
  const bool time = report.metric == "time";
  std::string head = "### shatterbench compare\n\n" + compare_preamble(report, o);
  const std::vector<const ComparisonRow*> rows = ranked_rows(report);
  std::size_t bad = 0;
  while (bad < rows.size() && is_bad(*rows[bad])) ++bad;
  std::string problems;
  if (bad > 0) {
    problems = fmt::format("#### Regressions and failures ({})\n\n", bad) + table_header(time);
    for (std::size_t i = 0; i < bad; ++i) problems += table_row(*rows[i], time);
    problems += "\n";
  }
  const std::string open = fmt::format("<details><summary>All {} rows</summary>\n\n", rows.size());
  const std::string close = "\n</details>\n";
  // The folded table takes what the limit leaves; rows that do not fit (the last: unchanged ones) are
  // counted instead. A note of the cut needs at most this much.
  constexpr std::size_t kNoteChars = 160;
  std::string table = table_header(time);
  std::size_t shown = 0;
  const std::size_t fixed = head.size() + problems.size() + open.size() + close.size() + kNoteChars;
  for (const ComparisonRow* r : rows) {
    const std::string line = table_row(*r, time);
    if (fixed + table.size() + line.size() > max_chars) break;
    table += line;
    ++shown;
  }
  if (shown < rows.size())
    table += fmt::format("\n{} of {} rows left out to fit a comment; `shatterbench compare` prints them all.\n",
                         rows.size() - shown, rows.size());
  std::string out = head + problems;
  // Even the regressions may not fit: then the folded table is left out and the text cut at a line.
  if (out.size() + open.size() + table.size() + close.size() > max_chars) {
    const std::string cut = "\n(cut to fit a comment; `shatterbench compare` prints the whole report)\n";
    // A line break at index i keeps i + 1 characters: i + 1 + cut.size() <= max_chars.
    std::size_t at = max_chars > cut.size() ? out.rfind('\n', max_chars - cut.size() - 1) : std::string::npos;
    out = out.substr(0, at == std::string::npos ? 0 : at + 1) + cut;
    return out;
  }
  return out + open + table + close;
}

}  // namespace shatter
