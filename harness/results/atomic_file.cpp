#include "harness/results/atomic_file.h"

#include <fmt/core.h>

#include <cerrno>
#include <cstring>
#include <random>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace shatter {
namespace fs = std::filesystem;

fs::path temporary_beside(const fs::path& path) {
  std::random_device rd;
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  return parent / fmt::format(".{}.partial-{:08x}", path.filename().string(), rd());
}

namespace {

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

}  // namespace

Status write_file_atomically(const fs::path& path, std::string_view content) {
  if (path.filename().empty()) return Error{path.string() + ": cannot write: not a file name"};
  const fs::path temp = temporary_beside(path);
  // O_EXCL: never write into a file someone else created under the same name.
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) return Error{path.string() + ": cannot write: " + std::strerror(errno)};
  const auto give_up = [&](const std::string& what, int error) {
    std::error_code ec;
    fs::remove(temp, ec);
    return Error{path.string() + ": " + what + ": " + std::strerror(error)};
  };
  if (!write_all(fd, content)) {
    const int error = errno;
    ::close(fd);
    return give_up("cannot write", error);
  }
  if (::fsync(fd) != 0) {
    const int error = errno;
    ::close(fd);
    return give_up("cannot flush", error);
  }
  if (::close(fd) != 0) return give_up("cannot write", errno);
  if (::rename(temp.c_str(), path.c_str()) != 0) return give_up("cannot move into place", errno);
  return {};
}

}  // namespace shatter
