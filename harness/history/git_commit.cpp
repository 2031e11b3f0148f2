#include "harness/history/git_commit.h"

#include "harness/process/child_process.h"

#include <cstdlib>
#include <sstream>

namespace shatter {
namespace {

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  return s;
}

std::string first_line(const std::string& s) { return trim(s.substr(0, s.find('\n'))); }

/// Runs git with `args` in `repo`; its standard output, or an error built from its first stderr line.
Result<std::string> git(const std::filesystem::path& repo, std::vector<std::string> args, const std::string& what) {
  args.insert(args.begin(), {"git", "-c", "core.quotepath=off"});
  Result<ChildOutput> r = run_child_output(args, repo);
  if (!r) return Error{what + ": " + r.error().message};
  if (!r->exit.exited || r->exit.code != 0)
    return Error{what + ": " + (r->err.empty() ? "git failed" : first_line(r->err))};
  return r->out;
}

}  // namespace

Result<CommitInfo> resolve_commit(const std::filesystem::path& repo, const std::string& revision, const std::string& branch) {
  const std::string what = "commit " + revision;
  if (revision.empty()) return Error{"commit: empty revision"};
  std::error_code ec;
  if (!repo.empty() && !std::filesystem::is_directory(repo, ec))
    return Error{what + ": no folder " + repo.string() + " (--repo names the git repository)"};
  Result<std::string> sha = git(repo, {"rev-parse", "--verify", "--quiet", "--end-of-options", revision + "^{commit}"}, what);
  if (!sha) {
    // rev-parse --quiet says nothing for an unknown revision: say it here.
    if (sha.error().message == what + ": git failed")
      return Error{what + ": not a commit of the repository at " + (repo.empty() ? std::string(".") : repo.string())};
    return sha.error();
  }
  CommitInfo info;
  info.sha = trim(*sha);
  Result<std::string> shown = git(repo, {"show", "-s", "--format=%P%n%ct", info.sha}, what);
  if (!shown) return shown.error();
  std::istringstream lines(*shown);
  std::string parents, time;
  std::getline(lines, parents);
  std::getline(lines, time);
  std::istringstream words(parents);
  for (std::string p; words >> p;) info.parents.push_back(p);
  info.time = std::strtoll(time.c_str(), nullptr, 10);
  // Ancestors counted: a commit has more than each of its parents, so commits of one second keep the
  // order of the history.
  Result<std::string> count = git(repo, {"rev-list", "--count", info.sha}, what);
  if (!count) return count.error();
  info.generation = std::strtoll(count->c_str(), nullptr, 10);

  Result<std::string> head = git(repo, {"rev-parse", "--verify", "--quiet", "HEAD"}, what);
  const bool at_head = head && trim(*head) == info.sha;
  info.branch = branch;
  if (at_head) {
    Result<std::string> status =
        git(repo, {"--no-optional-locks", "-c", "core.fsmonitor=false", "status", "--porcelain", "--untracked-files=no"}, what);
    info.dirty = status && !trim(*status).empty();
    if (info.branch.empty()) {
      Result<std::string> name = git(repo, {"symbolic-ref", "--short", "-q", "HEAD"}, what);
      if (name) info.branch = trim(*name);
    }
    for (const char* variable : {"GITHUB_HEAD_REF", "GITHUB_REF_NAME", "CI_COMMIT_REF_NAME"})
      if (const char* v = std::getenv(variable); info.branch.empty() && v != nullptr) info.branch = v;
  }
  return info;
}

}  // namespace shatter
