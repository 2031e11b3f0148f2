#include "harness/plugins/shared_object_check.h"

#include <elf.h>
#include <fcntl.h>
#include <link.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <vector>

namespace shatter {
namespace {

/// This process's ELF types (ElfW from link.h: Elf64_* on a 64-bit build).
using Header = ElfW(Ehdr);
using ProgramHeader = ElfW(Phdr);

#if defined(__x86_64__)
constexpr int kMachine = EM_X86_64;
#elif defined(__aarch64__)
constexpr int kMachine = EM_AARCH64;
#elif defined(__i386__)
constexpr int kMachine = EM_386;
#elif defined(__arm__)
constexpr int kMachine = EM_ARM;
#elif defined(__riscv)
constexpr int kMachine = EM_RISCV;
#elif defined(__powerpc64__)
constexpr int kMachine = EM_PPC64;
#else
constexpr int kMachine = -1;  // not checked on a machine not listed here
#endif

constexpr unsigned char kClass = sizeof(void*) == 8 ? ELFCLASS64 : ELFCLASS32;
constexpr unsigned char kData = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ ? ELFDATA2LSB : ELFDATA2MSB;

/// Reads exactly `size` bytes at `offset`; false on a short read.
bool read_at(int fd, void* to, std::size_t size, std::uint64_t offset) {
  auto* out = static_cast<char*>(to);
  while (size > 0) {
    const ssize_t n = ::pread(fd, out, size, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    out += n;
    size -= static_cast<std::size_t>(n);
    offset += static_cast<std::uint64_t>(n);
  }
  return true;
}

/// True when [offset, offset + count * entry) lies within `file_size` (no overflow).
bool table_inside(std::uint64_t offset, std::uint64_t count, std::uint64_t entry, std::uint64_t file_size) {
  if (count == 0) return true;
  if (entry == 0 || count > file_size / entry) return false;
  return offset <= file_size && count * entry <= file_size - offset;
}

Status check_open_file(int fd, const std::string& path) {
  const std::string at = "plugin " + path + ": ";
  struct stat st {};
  if (::fstat(fd, &st) != 0) return Error{at + "cannot read it: " + std::strerror(errno)};
  if (!S_ISREG(st.st_mode)) return Error{at + "not a regular file (a folder, FIFO, socket or device is not a plugin)"};
  const auto file_size = static_cast<std::uint64_t>(st.st_size);
  Header h{};
  if (file_size < sizeof h || !read_at(fd, &h, sizeof h, 0))
    return Error{at + "not a shared library (too short for an ELF header)"};
  if (std::memcmp(h.e_ident, ELFMAG, SELFMAG) != 0) return Error{at + "not a shared library (no ELF header)"};
  if (h.e_ident[EI_CLASS] != kClass || h.e_ident[EI_DATA] != kData)
    return Error{at + "a library of another word size or byte order than this machine's"};
  if (kMachine >= 0 && h.e_machine != kMachine)
    return Error{at + "a library for another machine (ELF machine " + std::to_string(h.e_machine) + ", this is " +
                 std::to_string(kMachine) + ")"};
  if (h.e_type != ET_DYN) return Error{at + "not a shared library (an ELF file of type " + std::to_string(h.e_type) + ")"};
  if (h.e_phentsize != sizeof(ProgramHeader) || h.e_phnum == 0 ||
      !table_inside(h.e_phoff, h.e_phnum, h.e_phentsize, file_size))
    return Error{at + "truncated or damaged (its program headers lie outside the file)"};
  if (!table_inside(h.e_shoff, h.e_shnum, h.e_shentsize, file_size))
    return Error{at + "truncated or damaged (its section headers lie outside the file)"};
  std::vector<ProgramHeader> segments(h.e_phnum);
  if (!read_at(fd, segments.data(), segments.size() * sizeof(ProgramHeader), h.e_phoff))
    return Error{at + "truncated (cannot read its program headers)"};
  bool loads = false;
  for (const ProgramHeader& p : segments) {
    if (p.p_type != PT_LOAD && p.p_type != PT_DYNAMIC) continue;
    loads = loads || p.p_type == PT_LOAD;
    // A segment's file bytes past the end would be mapped and fault (SIGBUS) when touched.
    if (!table_inside(p.p_offset, 1, p.p_filesz, file_size) && p.p_filesz != 0)
      return Error{at + "truncated (a segment ends at byte " + std::to_string(p.p_offset + p.p_filesz) +
                   ", the file has " + std::to_string(file_size) + ")"};
  }
  if (!loads) return Error{at + "not a loadable shared library (no loadable segment)"};
  return {};
}

}  // namespace

Status check_shared_object(const std::string& path) {
  // O_NONBLOCK: opening a FIFO with no writer returns at once instead of waiting for one.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) return Error{"plugin " + path + ": cannot load: " + std::strerror(errno)};
  Status s = check_open_file(fd, path);
  ::close(fd);
  return s;
}

}  // namespace shatter
