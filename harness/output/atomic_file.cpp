#include "harness/output/atomic_file.h"

#include "harness/output/folder_lock.h"

#include <fmt/core.h>

#include <cerrno>
#include <cstring>
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
    std::error_code kind_ec;
    const fs::file_status status = it->symlink_status(kind_ec);
    if (fs::is_regular_file(status)) {
      stale.push_back(it->path());
    } else if (fs::is_directory(status)) {
      // A staging folder holds the marker from its first moment; a folder without it is not ours.
      if (fs::is_empty(it->path(), kind_ec) || fs::exists(it->path() / kOutputMarker, kind_ec))
        stale.push_back(it->path());
    }
  }
  for (const fs::path& p : stale) fs::remove_all(p, ec);
}

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

  std::vector<fs::path> temps;
  const auto give_up = [&](const fs::path& path, const std::string& what, int error) {
    std::error_code ec;
    for (const fs::path& t : temps) fs::remove(t, ec);
    return Error{path.string() + ": " + what + ": " + std::strerror(error)};
  };
  for (std::size_t i = 0; i < files.size(); ++i) {
    const fs::path temp = temporary_beside(targets[i]);
    // O_EXCL: never write into a file someone else created under the same name.
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) return give_up(files[i].path, "cannot write", errno);
    temps.push_back(temp);
    if (!write_all(fd, files[i].content)) {
      const int error = errno;
      ::close(fd);
      return give_up(files[i].path, "cannot write", error);
    }
    if (::fsync(fd) != 0) {
      const int error = errno;
      ::close(fd);
      return give_up(files[i].path, "cannot flush", error);
    }
    if (::close(fd) != 0) return give_up(files[i].path, "cannot write", errno);
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (::rename(temps[i].c_str(), targets[i].c_str()) != 0) {
      const int error = errno;
      temps.erase(temps.begin(), temps.begin() + static_cast<std::ptrdiff_t>(i));
      return give_up(files[i].path, "cannot move into place", error);
    }
  }
  for (const FolderLock& lock : *locks) sync_folder(lock.folder());
  return {};
}

Status write_file_atomically(const fs::path& path, std::string_view content) {
  const FileContent file{path, content};
  return write_files_atomically(std::span<const FileContent>(&file, 1));
}

}  // namespace shatter
