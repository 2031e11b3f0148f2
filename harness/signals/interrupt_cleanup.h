#pragma once
/// What an interrupted command undoes before it ends (docs/stability.md, "Signals").
///
/// Design note: SIGINT, SIGTERM and SIGHUP end a command at any instruction, so what must not outlive
/// it (the children it started, the temporaries of a write in progress) is registered here while it
/// exists, and the handler kills and removes what is registered, then ends the process with the
/// signal's conventional status (the default action re-raised). The registry is the one process-wide
/// state of the harness, because a signal handler can reach nothing else; it is a fixed table written
/// with atomics and read by the handler with async-signal-safe calls only (kill, unlink, rmdir,
/// openat, getdents64). A child started with fork also asks the kernel to kill it when its parent
/// dies (PR_SET_PDEATHSIG), which covers a SIGKILL of the parent, where no handler runs.

#include <sys/types.h>

#include <filesystem>

namespace shatter {

/// Installs the handlers for SIGINT, SIGTERM and SIGHUP, once per process; a signal whose disposition
/// is not the default (a program that handles or ignores it itself) is left alone.
void install_interrupt_cleanup();

/// Restores the default disposition of the three signals: for a forked child, which must end as
/// the default says, not clean up after its parent.
void reset_interrupt_cleanup_in_child();

/// While alive, the child `pid` is killed with SIGKILL when the process is interrupted. Best effort:
/// past 64 registrations at once the newest are not registered.
class KilledOnInterrupt {
 public:
  explicit KilledOnInterrupt(pid_t pid);
  ~KilledOnInterrupt();
  KilledOnInterrupt(const KilledOnInterrupt&) = delete;
  KilledOnInterrupt& operator=(const KilledOnInterrupt&) = delete;

 private:
  int slot_ = -1;
};

/// While alive, `path` (a temporary file, or a staging folder and what it holds, three levels deep)
/// is removed when the process is interrupted. Best effort: a path longer than 4,095 bytes or past 64
/// registrations at once is not registered.
class RemovedOnInterrupt {
 public:
  explicit RemovedOnInterrupt(const std::filesystem::path& path);
  ~RemovedOnInterrupt();
  RemovedOnInterrupt(const RemovedOnInterrupt&) = delete;
  RemovedOnInterrupt& operator=(const RemovedOnInterrupt&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace shatter
