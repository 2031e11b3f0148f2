#include "harness/cli/history_access.h"

#include "harness/cli/command.h"
#include "harness/history/git_commit.h"
#include "harness/history/results_run.h"
#include "harness/history/store/postgres_connection.h"
#include "harness/results/run_context.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <map>

namespace shatter::cli {

void add_store_flags(CLI::App* cmd, StoreFlags& flags) {
  cmd->add_option("--db", flags.db,
                  "The history store: an SQLite file or a postgresql:// URL (default: SHATTERBENCH_DB, else "
                  "results/history.sqlite)");
  cmd->add_option("--lock-timeout", flags.lock_timeout_s, "Longest wait for another writer's lock on an SQLite store, s")
      ->check(CLI::Range(0.0, 3600.0))
      ->capture_default_str();
}

Result<HistoryStore> open_store(const StoreFlags& flags, bool create) {
  return HistoryStore::open(history_store_location(flags.db), StoreOptions{create, flags.lock_timeout_s});
}

void add_commit_flags(CLI::App* cmd, CommitFlags& flags) {
  cmd->add_option("--commit", flags.commit, "The commit the runs were made at (default: each file's context.commit)");
  cmd->add_option("--repo", flags.repo, "The git repository that knows the commit (default: the working folder)");
  cmd->add_option("--branch", flags.branch, "The branch (default: git's, or the CI's branch variable)");
}

int record_results(const std::vector<ResultsText>& results, const StoreFlags& store, const CommitFlags& commit,
                   std::ostream& report) {
  // Everything that can be wrong with the input is found before the store is touched.
  std::vector<RunRecord> runs;
  std::map<std::string, CommitInfo> commits;
  for (const ResultsText& r : results) {
    Result<RunRecord> run = run_from_results_text(r.text, r.source);
    if (!run) return fail_input(run.error().message);
    std::string revision = commit.commit;
    if (revision.empty()) {
      const nlohmann::json context = nlohmann::json::parse(run->context_json);
      revision = context.value("commit", std::string{});
      if (revision.empty()) return fail_input(r.source + ": context.commit is empty: give the commit with --commit");
    }
    auto known = commits.find(revision);
    if (known == commits.end()) {
      Result<CommitInfo> info = resolve_commit(std::filesystem::path(commit.repo.empty() ? std::string(".") : commit.repo), revision,
                                               commit.branch);
      if (!info) return fail_input(r.source + ": " + info.error().message);
      known = commits.emplace(revision, *info).first;
    }
    run->commit = known->second;
    runs.push_back(std::move(*run));
  }
  Result<HistoryStore> db = open_store(store, true);
  if (!db) return fail_input(db.error().message);
  // Every file in one transaction: a failure records none of them.
  Result<std::vector<bool>> added = db->record_all(runs);
  if (!added) return fail_input(added.error().message);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunRecord& run = runs[i];
    report << fmt::format("{} {} ({} {}, {} series) at {} into {}\n", (*added)[i] ? "recorded" : "already recorded",
                             run.source, run.kind, run.case_name, run.measurements.size(), run.commit.sha.substr(0, 12),
                             db->name());
  }
  return exit_ok;
}

void add_record_flags(CLI::App* cmd, RecordFlags& flags) {
  cmd->add_flag("--record", flags.record,
                "Record the run in the history store at this build's commit (docs/history.md; shatterbench history)");
  cmd->add_option("--db", flags.store.db,
                  "With --record: the history store, an SQLite file or a postgresql:// URL (default: SHATTERBENCH_DB, "
                  "else results/history.sqlite)");
}

Status check_record_target(const RecordFlags& flags) {
  if (!flags.record) {
    if (!flags.store.db.empty()) return Error{"--db: only with --record"};
    return {};
  }
  const std::string commit = current_context().commit;
  if (commit.empty()) return Error{"--record: this shatterbench was built outside a git checkout: record with history record --commit"};
  Result<CommitInfo> info = resolve_commit(".", commit);
  if (!info) return Error{"--record: " + info.error().message};
  // A build configured at an older commit records there: say so, since the checkout has moved on.
  if (Result<CommitInfo> head = resolve_commit(".", "HEAD"); head && head->sha != info->sha)
    std::fprintf(stderr, "shatterbench: warning: --record: this build is of commit %s, the checkout is at %s; the run is "
                 "recorded at %s (reconfigure, e.g. scripts/build, to build the checkout's commit)\n",
                 info->sha.substr(0, 12).c_str(), head->sha.substr(0, 12).c_str(), info->sha.substr(0, 12).c_str());
  // A store that is there (a file, a server) is opened now, so that a locked file, an unreachable
  // server or a store of a newer version stops the command before its run; a file not yet there is
  // made only when the run is recorded.
  const std::string location = history_store_location(flags.store.db);
  std::error_code ec;
  if (is_postgres_url(location) || std::filesystem::exists(location, ec)) {
    Result<HistoryStore> store = open_store(flags.store, true);
    if (!store) return Error{"--record: " + store.error().message};
  }
  return {};
}

int record_if_asked(const RecordFlags& flags, const std::string& text, const std::string& source) {
  if (!flags.record) return exit_ok;
  return record_results({{text, source}}, flags.store, CommitFlags{}, std::cerr);
}

Result<std::int64_t> since_time(HistoryStore& store, const std::string& revision, const std::string& repo) {
  if (revision.empty()) return std::numeric_limits<std::int64_t>::min();
  Result<CommitInfo> c = recorded_commit(store, revision, repo);
  if (!c) return Error{"--since: " + c.error().message};
  return c->time;
}

Result<CommitInfo> recorded_commit(HistoryStore& store, const std::string& revision, const std::string& repo) {
  Result<std::optional<CommitInfo>> found = store.find_commit(revision);
  if (!found) return found.error();
  if (*found) return **found;
  Result<CommitInfo> info = resolve_commit(std::filesystem::path(repo.empty() ? std::string(".") : repo), revision);
  if (!info) return info.error();
  Result<std::optional<CommitInfo>> recorded = store.find_commit(info->sha);
  if (!recorded) return recorded.error();
  if (!*recorded) return Error{fmt::format("commit {} ({}): no run recorded at it in {}", revision, info->sha.substr(0, 12), store.name())};
  return **recorded;
}

std::string series_label(const SeriesKey& k) {
  return fmt::format("{} · {} · {} · {}", k.case_name, k.subject, k.what, k.metric);
}

void add_series_filter_flags(CLI::App* cmd, SeriesFilter& f) {
  cmd->add_option("--case", f.case_name, "Only series of this case (a table's mesh file name, an accuracy case)");
  cmd->add_option("--kind", f.kind, "Only series of runs of this command: grid, accuracy or table");
  cmd->add_option("--subject", f.subject, "Only series whose subject contains this text (a cell, an algorithm)");
  cmd->add_option("--what", f.what, "Only series whose part contains this text (\"worst frame\", \"stage physics\")");
  cmd->add_option("--metric", f.metric, "Only series of this metric (cpu_ms, time_ms, instructions, volume_error, ...)");
  cmd->add_option("--fingerprint", f.fingerprint, "Only series of this build and machine fingerprint");
}

}  // namespace shatter::cli
