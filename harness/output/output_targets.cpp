#include "harness/output/output_targets.h"

#include "harness/output/output_folder.h"
#include "harness/output/own_output.h"

#include <algorithm>
#include <system_error>

#include <sys/stat.h>

namespace shatter {
namespace fs = std::filesystem;

namespace {

/// `path` made absolute, with symbolic links, `.` and `..` resolved as far as the path exists. A link
/// whose target does not exist yet is followed too (weakly_canonical stops at it), so two outputs that
/// would be written through links into one new file are found to be one.
fs::path resolved(const fs::path& path) {
  std::error_code ec;
  fs::path p = fs::absolute(path, ec);
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code link_ec;
    if (!fs::is_symlink(fs::symlink_status(p, link_ec)) || fs::exists(p, link_ec)) break;
    const fs::path target = fs::read_symlink(p, link_ec);
    if (link_ec) break;
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  fs::path canonical = fs::weakly_canonical(p, ec);
  return ec ? p.lexically_normal() : canonical;
}

/// True when `path` is `folder` or lies inside it (both resolved).
bool inside(const fs::path& path, const fs::path& folder) {
  const auto [fe, pe] = std::mismatch(folder.begin(), folder.end(), path.begin(), path.end());
  return fe == folder.end() || (std::next(fe) == folder.end() && fe->empty());
}

/// True when both exist and are one file (same device and inode: hard links too).
bool same_file(const fs::path& a, const fs::path& b) {
  struct stat sa {}, sb {};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

std::string kind_of(const fs::file_status& s) {
  switch (s.type()) {
    case fs::file_type::directory: return "a folder";
    case fs::file_type::character:
    case fs::file_type::block: return "a device";
    case fs::file_type::fifo: return "a FIFO";
    case fs::file_type::socket: return "a socket";
    default: return "not a regular file";
  }
}

Status check_one(const OutputTarget& t, const fs::path& where, const std::vector<fs::path>& protected_folders) {
  const std::string name = t.flag + ": " + t.path.string();
  std::error_code ec;
  if (t.folder) {
    if (Status s = check_replaceable_folder(t.path, t.flag); !s) return s;
  } else {
    const fs::file_status status = fs::status(t.path, ec);
    if (fs::exists(status) && !fs::is_regular_file(status))
      return Error{name + ": exists and is " + kind_of(status) + ", not a regular file: not replaced"};
    if (fs::exists(status) && !is_own_output_file(t.path))
      return Error{name + ": exists and is not a file shatterbench wrote: not replaced (name a new file, or move "
                          "this one away first)"};
    if (t.path.filename().empty() || t.path.filename() == "." || t.path.filename() == "..")
      return Error{name + ": not a file name"};
  }
  if (!t.baseline_update)
    if (Status s = check_outside_baselines(t.flag, t.path, protected_folders); !s) return s;
  for (const fs::path& folder : protected_folders) {
    const fs::path f = resolved(folder);
    if (t.folder && inside(f, where))
      return Error{name + ": holds the baseline folder " + folder.string() + ": not replaced"};
  }
  const fs::path parent = where.parent_path();
  if (!fs::is_directory(parent, ec)) return Error{name + ": the folder " + parent.string() + " does not exist"};
  return {};
}

}  // namespace

Status check_outside_baselines(const std::string& flag, const fs::path& path,
                               const std::vector<fs::path>& protected_folders) {
  const fs::path where = resolved(path);
  for (const fs::path& folder : protected_folders)
    if (inside(where, resolved(folder)))
      return Error{flag + ": " + path.string() + ": is in the baseline folder " + folder.string() +
                   "; baselines change only with grid --update-baseline"};
  return {};
}

std::vector<fs::path> baseline_folders(const fs::path& extra) {
  std::vector<fs::path> folders = {fs::path("results") / "baselines"};
  if (!extra.empty()) folders.push_back(extra);
  return folders;
}

Status check_outputs(const std::vector<OutputTarget>& targets, const std::vector<fs::path>& protected_folders,
                     const std::vector<fs::path>& inputs) {
  std::vector<std::pair<const OutputTarget*, fs::path>> seen;
  for (const OutputTarget& t : targets) {
    if (t.path.empty()) continue;
    const fs::path where = resolved(t.path);
    for (const fs::path& input : inputs) {
      if (input.empty()) continue;
      const fs::path in = resolved(input);
      if (!t.folder && (in == where || same_file(in, where)))
        return Error{t.flag + ": " + t.path.string() + ": is also an input (" + input.string() + "): not replaced"};
      if (t.folder && inside(in, where))
        return Error{t.flag + ": " + t.path.string() + ": holds the input " + input.string() + ": not replaced"};
    }
    if (Status s = check_one(t, where, protected_folders); !s) return s;
    for (const auto& [other, other_where] : seen) {
      if (!(where == other_where || same_file(where, other_where)) &&
          ((other->folder && inside(where, other_where)) || (t.folder && inside(other_where, where))))
        return Error{t.flag + " (" + t.path.string() + ") and " + other->flag + " (" + other->path.string() +
                     "): one lies inside the other folder output"};
      if (where == other_where || same_file(where, other_where))
        return Error{t.flag + " and " + other->flag + " name the same file " + t.path.string() +
                     (other->path == t.path ? "" : " (" + other->path.string() + ")") +
                     ": each output needs its own"};
    }
    seen.emplace_back(&t, where);
  }
  return {};
}

}  // namespace shatter
