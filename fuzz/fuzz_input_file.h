#pragma once
/// The fuzzers' bytes as a file: the mesh readers take a path, so the input is written to an anonymous
/// in-memory file (memfd) and read back through /proc/self/fd/N. No disk traffic, nothing left behind.

#include <cstddef>
#include <cstdint>
#include <string>
#include <sys/mman.h>
#include <unistd.h>

namespace shatter::fuzz {

/// An anonymous file holding a copy of the fuzzer input; closed on destruction.
class InputFile {
 public:
  InputFile(const std::uint8_t* data, std::size_t size) : fd_(::memfd_create("shatter_fuzz", 0)) {
    std::size_t written = 0;
    while (fd_ >= 0 && written < size) {
      const ssize_t n = ::write(fd_, data + written, size - written);
      if (n <= 0) break;
      written += static_cast<std::size_t>(n);
    }
  }
  ~InputFile() {
    if (fd_ >= 0) ::close(fd_);
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  /// Path that reads the file from the start.
  [[nodiscard]] std::string path() const { return "/proc/self/fd/" + std::to_string(fd_); }

 private:
  int fd_;
};

}  // namespace shatter::fuzz
