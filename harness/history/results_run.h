#pragma once
/// A results file as a run of the history (docs/history.md, "What a run keeps"): the grid JSON, the
/// accuracy JSON and the table JSON, each turned into its series and samples. The commit is the
/// caller's (git_commit.h): a results file names its build's commit, not the one it is recorded at.

#include "algorithms/core/result.h"
#include "harness/history/store/history_model.h"

#include <filesystem>
#include <string>

namespace shatter {

/// The run in `text`, the bytes of the results file `source`. Its id hashes the bytes, so the same
/// file is the same run. A file of another tool, malformed JSON, or a results file whose own keys are
/// wrong: an error naming the file and the key.
Result<RunRecord> run_from_results_text(const std::string& text, const std::string& source);

/// Reads `path` (at most kMaxResultsFileBytes) and calls run_from_results_text.
Result<RunRecord> read_results_run(const std::filesystem::path& path);

}  // namespace shatter
