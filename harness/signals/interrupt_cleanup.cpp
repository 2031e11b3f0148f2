#include "harness/signals/interrupt_cleanup.h"

#include <atomic>
#include <csignal>
#include <cstring>

#include <dirent.h>
#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace shatter {
namespace {

constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

/// A slot's states: free, being written (the handler skips it), ready.
enum SlotState : int { free_slot = 0, writing = 1, ready = 2 };

struct ChildSlot {
  std::atomic<int> state{free_slot};
  std::atomic<pid_t> pid{0};
};

struct PathSlot {
  std::atomic<int> state{free_slot};
  char path[kPathBytes] = {};
};

ChildSlot g_children[kSlots];
PathSlot g_paths[kSlots];
std::atomic<bool> g_installed{false};

template <class Slot>
int claim(Slot (&slots)[kSlots]) {
  for (int i = 0; i < kSlots; ++i) {
    int expected = free_slot;
    if (slots[i].state.compare_exchange_strong(expected, writing)) return i;
  }
  return -1;
}

/// Removes what `fd` (an open folder) holds, `depth` levels down; async-signal-safe.
void empty_folder(int fd, int depth) {
  alignas(8) char buffer[2048];
  for (;;) {
    const long n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer);
    if (n <= 0) return;
    bool removed_any = false;
    for (long at = 0; at < n;) {
      struct Entry {
        unsigned long long ino;
        long long off;
        unsigned short reclen;
        unsigned char type;
        char name[1];
      };
      const auto* e = reinterpret_cast<const Entry*>(buffer + at);
      at += e->reclen;
      const char* name = e->name;
      if (std::strcmp(name, ".") == 0 || std::strcmp(name, "..") == 0) continue;
      if (e->type == DT_DIR) {
        if (depth > 0) {
          const int child = ::openat(fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
          if (child >= 0) {
            empty_folder(child, depth - 1);
            ::close(child);
          }
        }
        removed_any |= ::unlinkat(fd, name, AT_REMOVEDIR) == 0;
      } else {
        removed_any |= ::unlinkat(fd, name, 0) == 0;
      }
    }
    // Entries were removed under the listing: list again from the start until nothing is left.
    if (!removed_any) return;
    ::lseek(fd, 0, SEEK_SET);
  }
}

void remove_path(const char* path) {
  if (::unlink(path) == 0) return;
  const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return;
  empty_folder(fd, 3);
  ::close(fd);
  ::rmdir(path);
}

void on_interrupt(int sig) {
  for (ChildSlot& c : g_children)
    if (c.state.load() == ready) ::kill(c.pid.load(), SIGKILL);
  for (PathSlot& p : g_paths)
    if (p.state.load() == ready) remove_path(p.path);
  // End as the signal's default action would: the status a shell and CI expect (128 + signal).
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

}  // namespace

void install_interrupt_cleanup() {
  if (g_installed.exchange(true)) return;
  for (const int sig : kSignals) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    for (const int other : kSignals) sigaddset(&action.sa_mask, other);  // one cleanup at a time
    action.sa_flags = SA_RESETHAND;
    ::sigaction(sig, &action, nullptr);
  }
}

void reset_interrupt_cleanup_in_child() {
  for (const int sig : kSignals) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == on_interrupt) ::signal(sig, SIG_DFL);
  }
  for (ChildSlot& c : g_children) c.state.store(free_slot);
  for (PathSlot& p : g_paths) p.state.store(free_slot);
}

KilledOnInterrupt::KilledOnInterrupt(pid_t pid) : slot_(claim(g_children)) {
  if (slot_ < 0) return;
  g_children[slot_].pid.store(pid);
  g_children[slot_].state.store(ready);
}

KilledOnInterrupt::~KilledOnInterrupt() {
  if (slot_ >= 0) g_children[slot_].state.store(free_slot);
}

RemovedOnInterrupt::RemovedOnInterrupt(const std::filesystem::path& path) {
  const std::string& text = path.native();
  if (text.empty() || text.size() >= kPathBytes) return;
  slot_ = claim(g_paths);
  if (slot_ < 0) return;
  std::memcpy(g_paths[slot_].path, text.c_str(), text.size() + 1);
  g_paths[slot_].state.store(ready);
}

RemovedOnInterrupt::~RemovedOnInterrupt() {
  if (slot_ >= 0) g_paths[slot_].state.store(free_slot);
}

}  // namespace shatter
