#include "harness/output/atomic_file.h"

#include "harness/output/folder_lock.h"
#include "harness/signals/interrupt_cleanup.h"

#include <fmt/core.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace shatter {
namespace fs = std::filesystem;

namespace {

fs::path folder_of(const fs::path& path) { return path.has_parent_path() ? path.parent_path() : fs::path("."); }

/// True when `name` is `.STEM.partial-` followed by exactly 8 hex digits.
bool is_temporary_of(const std::string& name, const std::string& stem) {
  const std::string prefix = "." + stem + ".partial-";
  if (name.size() != prefix.size() + 8 || name.compare(0, prefix.size(), prefix) != 0) return false;
  for (std::size_t i = prefix.size(); i < name.size(); ++i)
    if (!std::isxdigit(static_cast<unsigned char>(name[i]))) return false;
  return true;
}

/// Writes all of `content` to `fd`, retrying short writes and interrupted calls; errno on failure.
bool write_all(int fd, std::string_view content) {
  while (!content.empty()) {
    const ssize_t n = ::write(fd, content.data(), content.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    content.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

/// The kind of a non-regular file, for messages.
std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

/// Where the bytes for `path` go: the file a symbolic link names (the link is kept), else `path`.
Result<fs::path> write_target(const fs::path& path) {
  if (path.filename().empty()) return Error{path.string() + ": cannot write: not a file name"};
  std::error_code ec;
  fs::path target = path;
  if (fs::is_symlink(fs::symlink_status(path, ec))) {
    target = fs::weakly_canonical(fs::absolute(path), ec);
    if (ec) return Error{path.string() + ": cannot follow the symbolic link: " + ec.message()};
  }
  struct stat st {};
  if (::stat(folder_of(target).c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    return Error{path.string() + ": cannot write: the folder " + folder_of(target).string() + " does not exist"};
  if (::stat(target.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    return Error{path.string() + ": exists and is " + kind_of(st.st_mode) + ", not a regular file: not replaced"};
  return target;
}

/// Flushes a folder's entries (the renames) to disk; best effort.
void sync_folder(const fs::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

fs::path temporary_beside(const fs::path& path) {
  std::random_device rd;
  return folder_of(path) / fmt::format(".{}.partial-{:08x}", path.filename().string(), rd());
}

void remove_stale_temporaries(const fs::path& path) {
  const std::string stem = path.filename().string();
  std::error_code ec;
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(folder_of(path), ec), end; !ec && it != end; it.increment(ec)) {
    if (!is_temporary_of(it->path().filename().string(), stem)) continue;
    // Only a staging folder is known to be ours: it holds the marker from its first moment. A file of
    // that name may be the user's (a file being written has no name until it is complete), so it stays.
    std::error_code kind_ec;
    if (fs::is_directory(it->symlink_status(kind_ec)) && fs::exists(it->path() / kOutputMarker, kind_ec))
      stale.push_back(it->path());
  }
  for (const fs::path& p : stale) fs::remove_all(p, ec);
}

namespace {

/// One file of a set on its way to its target: written, flushed, then given a name and renamed.
struct PendingFile {
  int fd = -1;                                   ///< an unnamed file (O_TMPFILE), or -1
  fs::path named;                                ///< the named temporary, once there is one
  std::unique_ptr<RemovedOnInterrupt> removed;   ///< removes `named` if the process is interrupted
};

/// Creates and writes a named temporary beside `target` holding `content`; errno on failure.
bool write_named(const fs::path& target, std::string_view content, PendingFile& file) {
  for (int attempt = 0; attempt < 16; ++attempt) {
    const fs::path temp = temporary_beside(target);
    auto removed = std::make_unique<RemovedOnInterrupt>(temp);
    // O_EXCL: never write into a file someone else created under the same name.
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
      if (errno == EEXIST) continue;
      return false;
    }
    file.named = temp;
    file.removed = std::move(removed);
    const bool ok = write_all(fd, content) && ::fsync(fd) == 0;
    const int error = errno;
    if (::close(fd) != 0 || !ok) {
      errno = ok ? errno : error;
      return false;
    }
    return true;
  }
  errno = EEXIST;
  return false;
}

/// Gives the unnamed `file` a fresh temporary name beside `target`; false (errno set) when it cannot
/// be linked (no /proc, another file system's rules): the caller then writes a named one.
bool link_unnamed(const fs::path& target, PendingFile& file) {
  const std::string self = "/proc/self/fd/" + std::to_string(file.fd);
  for (int attempt = 0; attempt < 16; ++attempt) {
    const fs::path temp = temporary_beside(target);
    auto removed = std::make_unique<RemovedOnInterrupt>(temp);
    if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, temp.c_str(), AT_SYMLINK_FOLLOW) == 0) {
      file.named = temp;
      file.removed = std::move(removed);
      return true;
    }
    if (errno != EEXIST) return false;
  }
  errno = EEXIST;
  return false;
}

}  // namespace

Status write_files_atomically(std::span<const FileContent> files) {
  std::vector<fs::path> targets;
  std::vector<fs::path> folders;
  for (const FileContent& f : files) {
    Result<fs::path> target = write_target(f.path);
    if (!target) return target.error();
    targets.push_back(*target);
    folders.push_back(folder_of(*target));
  }
  Result<std::vector<FolderLock>> locks = lock_folders(folders);
  if (!locks) return locks.error();
  // Checked again under the lock: another process may have put something there since.
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (Result<fs::path> again = write_target(files[i].path); !again) return again.error();
    remove_stale_temporaries(targets[i]);
  }

  // Each file is written as an unnamed file of its folder (O_TMPFILE): a run killed while writing
  // leaves nothing behind and no name is ever taken. Where the file system has none, a named
  // temporary is written instead (removed on an interrupt; a SIGKILL leaves it, hidden, and it is
  // never removed later, since a file of that name may be the user's).
  std::vector<PendingFile> pending(files.size());
  const auto give_up = [&](const fs::path& path, const std::string& what, int error) {
    for (PendingFile& p : pending) {
      if (p.fd >= 0) ::close(p.fd);
      if (!p.named.empty()) ::unlink(p.named.c_str());
    }
    return Error{path.string() + ": " + what + ": " + std::strerror(error)};
  };
  for (std::size_t i = 0; i < files.size(); ++i) {
    PendingFile& p = pending[i];
    p.fd = ::open(folders[i].c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    if (p.fd < 0) {
      if (!write_named(targets[i], files[i].content, p)) return give_up(files[i].path, "cannot write", errno);
      continue;
    }
    if (!write_all(p.fd, files[i].content)) return give_up(files[i].path, "cannot write", errno);
    if (::fsync(p.fd) != 0) return give_up(files[i].path, "cannot flush", errno);
  }
  // Every file is complete: each gets its temporary name, then all are renamed into place, in order.
  for (std::size_t i = 0; i < files.size(); ++i) {
    PendingFile& p = pending[i];
    if (p.fd < 0) continue;
    const bool linked = link_unnamed(targets[i], p);
    ::close(p.fd);
    p.fd = -1;
    if (!linked && !write_named(targets[i], files[i].content, p)) return give_up(files[i].path, "cannot write", errno);
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (::rename(pending[i].named.c_str(), targets[i].c_str()) != 0) {
      const int error = errno;
      for (std::size_t done = 0; done < i; ++done) pending[done].named.clear();
      return give_up(files[i].path, "cannot move into place", error);
    }
    pending[i].named.clear();
  }
  for (const FolderLock& lock : *locks) sync_folder(lock.folder());
  return {};
}

Status write_file_atomically(const fs::path& path, std::string_view content) {
  const FileContent file{path, content};
  return write_files_atomically(std::span<const FileContent>(&file, 1));
}

}  // namespace shatter
