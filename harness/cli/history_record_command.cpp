#include "algorithms/core/bounded_read.h"
#include "harness/cli/command.h"
#include "harness/cli/history_access.h"
#include "harness/cli/history_subcommands.h"
#include "harness/history/results_run.h"
#include "harness/limits.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

namespace shatter::cli {
namespace {

namespace fs = std::filesystem;

struct RecordOptions {
  std::vector<std::string> files;
  StoreFlags store;
  CommitFlags commit;
};

Result<std::vector<ResultsText>> read_all(const std::vector<fs::path>& files) {
  std::vector<ResultsText> out;
  for (const fs::path& f : files) {
    Result<std::string> text = read_file_bounded(f, kMaxResultsFileBytes, "results file");
    if (!text) return text.error();
    out.push_back({std::move(*text), f.string()});
  }
  return out;
}

int run_record(const RecordOptions& o) {
  std::vector<fs::path> files(o.files.begin(), o.files.end());
  Result<std::vector<ResultsText>> texts = read_all(files);
  if (!texts) return fail_input(texts.error().message);
  return record_results(*texts, o.store, o.commit, std::cout);
}

/// True when `text` is a shatterbench results file (the keys that say so), read cheaply.
bool looks_like_results(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  return j.is_object() && j.contains("schema_version") && j.contains("context") &&
         (j.contains("cells") || j.value("kind", std::string{}) == "accuracy" || j.value("kind", std::string{}) == "table");
}

int run_import(const RecordOptions& o) {
  // Files named on the command line must be results; in a folder, other JSON (Google Benchmark's, a
  // CI's metadata) is passed over and counted.
  std::vector<fs::path> named, found;
  for (const std::string& p : o.files) {
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<fs::path> inside;
      for (fs::recursive_directory_iterator it(p, fs::directory_options::none, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_regular_file(ec) && it->path().extension() == ".json") inside.push_back(it->path());
      if (ec) return fail_input(fmt::format("{}: {}", p, ec.message()));
      std::sort(inside.begin(), inside.end());
      found.insert(found.end(), inside.begin(), inside.end());
    } else {
      named.push_back(p);
    }
  }
  Result<std::vector<ResultsText>> texts = read_all(named);
  if (!texts) return fail_input(texts.error().message);
  Result<std::vector<ResultsText>> more = read_all(found);
  if (!more) return fail_input(more.error().message);
  int skipped = 0;
  for (ResultsText& t : *more) {
    if (looks_like_results(t.text)) texts->push_back(std::move(t));
    else ++skipped;
  }
  if (skipped > 0) std::cerr << fmt::format("shatterbench: import: passed over {} JSON file(s) that are not results\n", skipped);
  if (texts->empty()) return fail_input("import: no results file found");
  return record_results(*texts, o.store, o.commit, std::cout);
}

}  // namespace

void add_history_record_commands(CLI::App& history, int& exit_code) {
  auto r = std::make_shared<RecordOptions>();
  CLI::App* record = history.add_subcommand("record", "Record results files (grid, accuracy, table JSON) at their commit");
  record->add_option("RESULTS", r->files, "Results JSON files")->required();
  add_store_flags(record, r->store);
  add_commit_flags(record, r->commit);
  record->callback([r, &exit_code] { exit_code = run_record(*r); });

  auto i = std::make_shared<RecordOptions>();
  CLI::App* import = history.add_subcommand(
      "import", "Record existing results: files and folders (every results JSON below them), e.g. CI artifacts");
  import->add_option("PATHS", i->files, "Results files or folders")->required();
  add_store_flags(import, i->store);
  add_commit_flags(import, i->commit);
  import->callback([i, &exit_code] { exit_code = run_import(*i); });
}

}  // namespace shatter::cli
