#include "harness/output/folder_lock.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>
#include <mutex>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace shatter {
namespace fs = std::filesystem;

struct FolderLock::Held {
  fs::path folder;
  int fd = -1;
  ~Held() {
    if (fd >= 0) ::close(fd);  // closing the last descriptor releases the flock
  }
};

namespace {

/// The locks this process holds, by folder: flock belongs to an open file description, so a second
/// open() of a folder this process has locked would wait for itself.
std::mutex table_mutex;
std::map<std::string, std::weak_ptr<FolderLock::Held>>& held_table() {
  static std::map<std::string, std::weak_ptr<FolderLock::Held>> table;
  return table;
}

/// The key of a folder in the table: its canonical path (so `a/../a` and `a` are one folder).
std::string table_key(const fs::path& folder) {
  std::error_code ec;
  const fs::path canonical = fs::canonical(folder, ec);
  return ec ? fs::absolute(folder).lexically_normal().string() : canonical.string();
}

}  // namespace

Result<FolderLock> FolderLock::acquire(const fs::path& folder) {
  const std::string key = table_key(folder);
  std::lock_guard<std::mutex> guard(table_mutex);
  if (auto held = held_table()[key].lock()) return FolderLock(held);
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return Error{folder.string() + ": cannot open the folder: " + std::strerror(errno)};
  auto held = std::make_shared<Held>();
  held->folder = folder;
  held->fd = fd;
  while (::flock(fd, LOCK_EX) != 0) {
    if (errno == EINTR) continue;
    // A file system without flock (some network mounts): write unlocked rather than not at all.
    if (errno == ENOLCK || errno == EOPNOTSUPP || errno == EINVAL) break;
    return Error{folder.string() + ": cannot lock the folder: " + std::strerror(errno)};
  }
  held_table()[key] = held;
  return FolderLock(held);
}

const fs::path& FolderLock::folder() const { return held_->folder; }

Result<std::vector<FolderLock>> lock_folders(std::vector<fs::path> folders) {
  std::vector<std::pair<std::string, fs::path>> keyed;
  for (const fs::path& f : folders) keyed.emplace_back(table_key(f), f);
  std::sort(keyed.begin(), keyed.end());
  keyed.erase(std::unique(keyed.begin(), keyed.end(),
                          [](const auto& a, const auto& b) { return a.first == b.first; }),
              keyed.end());
  std::vector<FolderLock> locks;
  for (const auto& [key, folder] : keyed) {
    Result<FolderLock> lock = FolderLock::acquire(folder);
    if (!lock) return lock.error();
    locks.push_back(std::move(*lock));
  }
  return locks;
}

}  // namespace shatter
