#include "algorithms/core/bounded_read.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace shatter {
namespace {

/// Closes a file descriptor when it goes out of scope.
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  [[nodiscard]] int get() const { return fd_; }

 private:
  int fd_;
};

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string too_large(const std::string& file, std::string_view what, std::uint64_t max_bytes) {
  return file + ": larger than the limit of " + std::to_string(max_bytes) + " bytes per " + std::string(what);
}

}  // namespace

Result<std::string> read_file_bounded(const std::filesystem::path& path, std::uint64_t max_bytes,
                                      std::string_view what) {
  const std::string file = path.string();
  const std::string kind(what);
  // Refuse what is neither a regular file nor a pipe before opening it: opening a device can block
  // or have effects of its own (a tape rewinds, a terminal waits).
  struct stat before {};
  if (::stat(file.c_str(), &before) != 0) return Error{file + ": cannot open the " + kind + ": " + std::strerror(errno)};
  if (!S_ISREG(before.st_mode) && !S_ISFIFO(before.st_mode))
    return Error{file + ": cannot read the " + kind + ": " + kind_of(before.st_mode)};
  const FileDescriptor fd(::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY));
  if (fd.get() < 0) return Error{file + ": cannot open the " + kind + ": " + std::strerror(errno)};
  // The descriptor's own status: the path may have been replaced between stat and open.
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) return Error{file + ": cannot read the " + kind + ": " + std::strerror(errno)};
  if (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode))
    return Error{file + ": cannot read the " + kind + ": " + kind_of(st.st_mode)};
  std::string text;
  if (S_ISREG(st.st_mode)) {
    const auto size = static_cast<std::uint64_t>(st.st_size);
    if (size > max_bytes)
      return Error{too_large(file, what, max_bytes) + " (the file has " + std::to_string(size) + " bytes)"};
    text.reserve(static_cast<std::size_t>(size));
  }
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      return Error{file + ": cannot read the " + kind + ": " + std::strerror(errno)};
    }
    if (n == 0) break;
    if (text.size() + static_cast<std::uint64_t>(n) > max_bytes) return Error{too_large(file, what, max_bytes)};
    text.append(buffer, static_cast<std::size_t>(n));
  }
  return text;
}

}  // namespace shatter
