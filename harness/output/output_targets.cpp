#include "harness/output/output_targets.h"

#include "harness/output/output_folder.h"

#include <algorithm>
#include <system_error>

#include <sys/stat.h>

namespace shatter {
namespace fs = std::filesystem;

namespace {

/// `path` made absolute, with symbolic links, `.` and `..` resolved as far as the path exists.
fs::path resolved(const fs::path& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path), ec);
  return ec ? fs::absolute(path).lexically_normal() : p;
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

Status check_outputs(const std::vector<OutputTarget>& targets, const std::vector<fs::path>& protected_folders) {
  std::vector<std::pair<const OutputTarget*, fs::path>> seen;
  for (const OutputTarget& t : targets) {
    if (t.path.empty()) continue;
    const fs::path where = resolved(t.path);
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
