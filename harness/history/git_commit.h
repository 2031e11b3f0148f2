#pragma once
/// What git knows of a commit, for the history (`history record --commit REV`). git runs as a child
/// process with the revision as one argument after `--end-of-options`: a revision from the user is
/// data, never an option or shell syntax.

#include "algorithms/core/result.h"
#include "harness/history/store/history_model.h"

#include <filesystem>
#include <string>

namespace shatter {

/// The commit `revision` names in the repository at `repo`: sha, parents and committer time. When it
/// is the checkout's HEAD, also the branch (or, on a detached HEAD, the CI's branch variable:
/// GITHUB_HEAD_REF, GITHUB_REF_NAME, CI_COMMIT_REF_NAME) and whether tracked files have changes.
/// `branch`, when not empty, is taken as the branch instead. A revision git does not know, or no git
/// repository at `repo`: one-line error.
Result<CommitInfo> resolve_commit(const std::filesystem::path& repo, const std::string& revision,
                                  const std::string& branch = {});

}  // namespace shatter
