#include "harness/output/output_folder.h"

#include "harness/output/atomic_file.h"
#include "harness/output/folder_lock.h"
#include "harness/signals/interrupt_cleanup.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace shatter {
namespace fs = std::filesystem;

namespace {

constexpr std::string_view kMarkerText =
    "This folder was written by shatterbench; the next run that writes here replaces it whole.\n";

/// Swaps the folders `a` and `b` in one step; false (errno set) when the file system cannot.
bool exchange(const fs::path& a, const fs::path& b) {
  return ::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0;
}

}  // namespace

Status check_replaceable_folder(const fs::path& dir, std::string_view flag) {
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (!fs::exists(status)) return {};
  const std::string where = std::string(flag) + ": " + dir.string();
  if (!fs::is_directory(status)) return Error{where + ": exists and is not a folder: not replaced"};
  if (fs::is_empty(dir, ec) || fs::exists(dir / kOutputMarker, ec)) return {};
  return Error{where + ": a folder that shatterbench did not write, and not empty: not replaced (name a new or "
                       "empty folder)"};
}

Status write_folder_atomically(const fs::path& named, const FolderFiller& fill) {
  std::error_code ec;
  // A symbolic link to a folder stays a link: the folder it names is replaced.
  const fs::path dir = fs::is_symlink(fs::symlink_status(named, ec)) ? fs::weakly_canonical(fs::absolute(named), ec) : named;
  if (dir.filename().empty() || dir.filename() == "." || dir.filename() == "..")
    return Error{dir.string() + ": cannot write: not a folder name"};
  const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec)) return Error{dir.string() + ": the folder " + parent.string() + " does not exist"};
  Result<FolderLock> lock = FolderLock::acquire(parent);
  if (!lock) return lock.error();
  if (Status s = check_replaceable_folder(dir, "output"); !s) return s;
  remove_stale_temporaries(dir);

  const fs::path staging = temporary_beside(dir);
  const RemovedOnInterrupt removed_if_interrupted(staging);
  if (!fs::create_directory(staging, ec)) return Error{staging.string() + ": cannot create folder: " + ec.message()};
  const auto give_up = [&](Error e) {
    std::error_code ignored;
    fs::remove_all(staging, ignored);
    return e;
  };
  if (Status s = write_file_atomically(staging / kOutputMarker, kMarkerText); !s) return give_up(s.error());
  if (Status s = fill(staging); !s) return give_up(s.error());

  if (!fs::exists(fs::symlink_status(dir, ec))) {
    if (::rename(staging.c_str(), dir.c_str()) != 0)
      return give_up(Error{dir.string() + ": cannot move into place: " + std::strerror(errno)});
  } else if (exchange(staging, dir)) {
    fs::remove_all(staging, ec);  // now the old content
  } else {
    // No RENAME_EXCHANGE here: the old folder steps aside first, and comes back if the new one cannot go in.
    const fs::path aside = temporary_beside(dir);
    if (::rename(dir.c_str(), aside.c_str()) != 0)
      return give_up(Error{dir.string() + ": cannot replace: " + std::strerror(errno)});
    if (::rename(staging.c_str(), dir.c_str()) != 0) {
      const int error = errno;
      ::rename(aside.c_str(), dir.c_str());
      return give_up(Error{dir.string() + ": cannot move into place: " + std::strerror(error)});
    }
    fs::remove_all(aside, ec);
  }
  const int fd = ::open(parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
  return {};
}

}  // namespace shatter
