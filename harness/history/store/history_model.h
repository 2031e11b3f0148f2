#pragma once
/// What the history store keeps (docs/history.md, "The model"): runs at commits, and per run one
/// measurement (every sample) of each series it holds. A series is one figure of one thing measured
/// on one build and machine setup: a cell's worst frame in CPU time, a stage's instructions, a
/// fracturer's volume error on a mesh. Runs of different fingerprints are different series, as
/// `compare` refuses to mix them.

#include <cstdint>
#include <string>
#include <vector>

namespace shatter {

/// Which way a metric improves; `none` never regresses (counts that describe a run, not judge it).
enum class Better { lower, higher, none };

/// "lower", "higher" or "none".
const char* better_name(Better b);

/// A commit as git knows it.
struct CommitInfo {
  std::string sha;                   ///< 40 hex digits
  std::vector<std::string> parents;  ///< their shas
  std::string branch;                ///< branch the run was made on ("" unknown)
  bool dirty = false;                ///< the working tree had changes to tracked files
  std::int64_t time = 0;             ///< committer time, s since 1970 (orders the history)
  std::int64_t generation = 0;       ///< commits that are ancestors of it (orders commits of one second)
};

/// What a series is. Its id is a hash of every field but unit and better (series_id()).
struct SeriesKey {
  std::string kind;         ///< "grid", "accuracy" or "table": the command that made the run
  std::string case_name;    ///< the case (grid), the accuracy case, or the mesh (table)
  std::string fingerprint;  ///< the build and machine fingerprint (run_context.h)
  std::string subject;      ///< what was measured: "100 x 25 voronoi/voronoi/connection-count", "plane-slice 25 fragments"
  std::string what;         ///< which part: "worst frame", "stage fracture", "accuracy", "fracture"
  std::string metric;       ///< "cpu_ms", "time_ms", "instructions", "volume_error", ...
  std::string unit;         ///< "ms", "instructions", "" (a ratio)
  Better better = Better::lower;
};

/// The series' id: FNV-1a (64 bit) of kind, case, fingerprint, subject, what and metric.
std::int64_t series_id(const SeriesKey& key);

/// One series in one run: every sample (one per repetition; one value for a figure that a run has once).
struct Measurement {
  SeriesKey series;
  std::vector<double> samples;
};

/// One run, as recorded.
struct RunRecord {
  std::string id;             ///< FNV-1a of the results file's bytes: the same file is the same run
  CommitInfo commit;
  std::string kind;           ///< as SeriesKey::kind
  std::string case_name;
  std::string fingerprint;
  std::string machine;        ///< host name
  std::string source;         ///< the results file's name, for the user
  std::string context_json;   ///< the results' `context` block
  std::string settings_json;  ///< the case and the run's settings
  bool passed = true;         ///< the run's own verdict (budgets and result checks)
  std::vector<Measurement> measurements;
};

/// A series as listed by the store.
struct SeriesInfo {
  std::int64_t id = 0;
  SeriesKey key;
};

/// One run's measurement of one series, with its commit (series_runs()).
struct SeriesRun {
  std::string run_id;
  std::string commit;         ///< sha
  std::int64_t commit_time = 0;
  std::string branch;         ///< the branch the run was recorded on
  bool passed = true;         ///< the run's verdict
  std::vector<double> samples;
  std::int64_t generation = 0;  ///< of the commit (CommitInfo::generation)
  bool dirty = false;           ///< the run was made from a working tree with changes
};

/// A run as listed at its commit.
struct RunSummary {
  std::string id;
  std::string source;
  std::string kind;
  std::string case_name;
  bool passed = true;
};

/// An acknowledged change: the gate judges the series from `commit` on.
struct Acknowledgement {
  std::int64_t series_id = 0;  ///< the series acknowledged
  std::string commit;          ///< the commit from which the gate judges it (sha)
  std::string note;            ///< why
  std::string created;         ///< UTC ISO 8601
  std::int64_t commit_time = 0;  ///< of the commit (read back; orders it among the series' points)
  std::int64_t generation = 0;   ///< of the commit (read back)
};

}  // namespace shatter
