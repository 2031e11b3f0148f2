#include "harness/history/dashboard_data.h"

#include <algorithm>
#include <limits>
#include <map>

namespace shatter {

Result<nlohmann::json> dashboard_data(HistoryStore& store, const SeriesFilter& filter, const HistoryGateSettings& gate) {
  using Json = nlohmann::json;
  std::map<std::pair<std::int64_t, std::string>, std::size_t> commit_index;  // (time, sha) in commit order
  std::map<std::pair<std::int64_t, std::string>, std::string> branch_of;
  struct Entry {
    Json series;
    std::vector<std::pair<std::int64_t, std::string>> commits;  // of each point, resolved to indices below
    bool regressed = false;
  };
  std::vector<Entry> entries;
  Status visited = store.visit_series_runs(
      filter, std::numeric_limits<std::int64_t>::min(), [&](const SeriesInfo& info, std::vector<SeriesRun>& runs) {
        const std::vector<CommitPoint> points = commit_points(runs);
        if (points.empty()) return Status{};
        Entry e;
        const SeriesKey& k = info.key;
        e.series = Json{{"kind", k.kind},       {"case", k.case_name}, {"subject", k.subject},
                        {"what", k.what},       {"metric", k.metric},  {"unit", k.unit},
                        {"better", better_name(k.better)}, {"fingerprint", k.fingerprint}};
        Json rows = Json::array();
        for (const CommitPoint& p : points) {
          const auto [lo, hi] = std::minmax_element(p.samples.begin(), p.samples.end());
          rows.push_back(Json::array({0, p.median, *lo, *hi, p.samples.size()}));
          e.commits.emplace_back(p.time, p.commit);
          commit_index.emplace(std::make_pair(p.time, p.commit), 0);
          branch_of.emplace(std::make_pair(p.time, p.commit), p.branch);
        }
        e.series["points"] = std::move(rows);
        Json changes = Json::array();
        for (const SeriesChange& c : series_changes(points, k.better, gate.change_points))
          changes.push_back(Json{{"index", c.index},   {"commit", c.commit},   {"before", c.median_before},
                                 {"after", c.median_after}, {"change", c.change}, {"pvalue", c.pvalue},
                                 {"kind", change_kind_name(c.kind)}});
        e.series["changes"] = std::move(changes);
        if (k.better != Better::none) {
          const SeriesVerdict v = judge_newest(points, 0, k.better, k.unit, gate);
          e.series["newest"] = Json{{"verdict", gate_verdict_name(v.verdict)}, {"change", v.change},
                                    {"pvalue", v.pvalue}, {"note", v.note}};
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
    commits.push_back(Json{{"sha", key.second}, {"time", key.first}, {"branch", branch_of.at(key)}});
  }
  std::stable_partition(entries.begin(), entries.end(), [](const Entry& e) { return e.regressed; });
  Json series = Json::array();
  for (Entry& e : entries) {
    Json& rows = e.series["points"];
    for (std::size_t i = 0; i < rows.size(); ++i) rows[i][0] = commit_index.at(e.commits[i]);
    series.push_back(std::move(e.series));
  }
  return Json{{"store", store.name()}, {"commits", std::move(commits)}, {"series", std::move(series)}};
}

}  // namespace shatter
