#include "harness/history/dashboard_data.h"

#include "harness/history/series_fracturer.h"

#include <fmt/core.h>

#include <algorithm>
#include <map>
#include <tuple>

namespace shatter {
namespace {

/// A commit's place in the history's order (committer time, generation, sha).
using CommitKey = std::tuple<std::int64_t, std::int64_t, std::string>;

}  // namespace

Result<nlohmann::json> dashboard_data(HistoryStore& store, const SeriesFilter& filter, const HistoryGateSettings& gate,
                                      std::int64_t since_time) {
  using Json = nlohmann::json;
  std::map<CommitKey, std::size_t> commit_index;  // filled in commit order below
  std::map<CommitKey, std::string> branch_of;
  struct Entry {
    Json series;
    std::vector<CommitKey> commits;  // of each point, resolved to indices below
    bool regressed = false;
  };
  std::vector<Entry> entries;
  // An acknowledged step is not open: the newest commit is judged from the latest acknowledgement on,
  // as the gate does.
  Result<std::vector<Acknowledgement>> acks = store.all_acknowledgements();
  if (!acks) return acks.error();
  std::multimap<std::int64_t, Acknowledgement> acks_of;
  for (Acknowledgement& a : *acks) acks_of.emplace(a.series_id, std::move(a));
  Status visited = store.visit_series_runs(filter, since_time, [&](const SeriesInfo& info, std::vector<SeriesRun>& runs) {
    const std::vector<CommitPoint> points = commit_points(runs);
    if (points.empty()) return Status{};
    Entry e;
    const SeriesKey& k = info.key;
    e.series = Json{{"id", fmt::format("{:016x}", static_cast<std::uint64_t>(info.id))},
                    {"kind", k.kind},
                    {"case", k.case_name},
                    {"subject", k.subject},
                    {"what", k.what},
                    {"metric", k.metric},
                    {"unit", k.unit},
                    {"better", better_name(k.better)},
                    {"fingerprint", k.fingerprint},
                    {"fracturer", series_fracturer(k)}};
    Json rows = Json::array();
    for (const CommitPoint& p : points) {
      const auto [lo, hi] = std::minmax_element(p.samples.begin(), p.samples.end());
      rows.push_back(Json::array({0, p.median, *lo, *hi, p.samples.size()}));
      CommitKey key{p.time, p.generation, p.commit};
      commit_index.emplace(key, 0);
      branch_of.emplace(key, p.branch);
      e.commits.push_back(std::move(key));
    }
    e.series["points"] = std::move(rows);
    Json changes = Json::array();
    for (const SeriesChange& c : series_changes(points, k.better, gate.change_points))
      changes.push_back(Json{{"index", c.index},   {"commit", c.commit},   {"before", c.median_before},
                             {"after", c.median_after}, {"change", c.change}, {"pvalue", c.pvalue},
                             {"kind", change_kind_name(c.kind)}});
    e.series["changes"] = std::move(changes);
    if (k.better != Better::none) {
      std::size_t first = 0;
      const Acknowledgement* latest = nullptr;
      for (auto a = acks_of.lower_bound(info.id); a != acks_of.end() && a->first == info.id; ++a)
        for (std::size_t i = 0; i < points.size(); ++i)
          if (CommitKey{points[i].time, points[i].generation, points[i].commit} >=
              CommitKey{a->second.commit_time, a->second.generation, a->second.commit}) {
            if (i >= first) latest = &a->second;
            first = std::max(first, i);
            break;
          }
      const SeriesVerdict v = judge_newest(points, first, k.better, k.unit, gate);
      e.series["newest"] = Json{{"verdict", gate_verdict_name(v.verdict)}, {"change", v.change},
                                {"pvalue", v.pvalue}, {"note", v.note}};
      if (latest != nullptr)
        e.series["newest"]["acknowledged"] = Json{{"commit", latest->commit}, {"note", latest->note}};
      e.regressed = v.verdict == GateVerdict::regressed;
    }
    entries.push_back(std::move(e));
    return Status{};
  });
  if (!visited) return visited.error();
  Json commits = Json::array();
  std::size_t next = 0;
  for (auto& [key, index] : commit_index) {
    index = next++;
    commits.push_back(Json{{"sha", std::get<2>(key)}, {"time", std::get<0>(key)}, {"branch", branch_of.at(key)}});
  }
  std::stable_partition(entries.begin(), entries.end(), [](const Entry& e) { return e.regressed; });
  Json series = Json::array();
  for (Entry& e : entries) {
    Json& rows = e.series["points"];
    for (std::size_t i = 0; i < rows.size(); ++i) rows[i][0] = commit_index.at(e.commits[i]);
    series.push_back(std::move(e.series));
  }
  const ChangePointSettings& cp = gate.change_points;
  return Json{{"format", kDashboardDataFormat},
              {"store", store.name()},
              {"settings", {{"window", cp.window}, {"max_pvalue", cp.max_pvalue}, {"min_magnitude", cp.min_magnitude}}},
              {"commits", std::move(commits)},
              {"series", std::move(series)}};
}

}  // namespace shatter
