#pragma once
/// An advisory lock on a folder, held while shatterbench writes into it.
///
/// Every output goes through harness/output/, and every write there holds the lock of the folder it
/// writes into: two shatterbench processes writing one output set (a results JSON and its CSV twin)
/// are serialised, so the set always comes from one run, and a writer that holds the lock knows that
/// any temporary it finds there was left by a run that was killed. The lock is `flock` on the folder
/// itself (no lock file is left behind). Within one process the lock is shared: a writer that already
/// holds a folder (an output set, a report being drawn into its staging folder) may write more files
/// there. On a file system without `flock` support the write goes on unlocked.

#include "algorithms/core/result.h"

#include <filesystem>
#include <memory>
#include <vector>

namespace shatter {

/// A held lock on one folder; released when the last copy is destroyed.
class FolderLock {
 public:
  /// Waits for and takes the lock of `folder` (which must exist). Error when it cannot be opened.
  static Result<FolderLock> acquire(const std::filesystem::path& folder);

  /// The locked folder, as it was named to acquire().
  [[nodiscard]] const std::filesystem::path& folder() const;

  struct Held;  ///< the open folder and its flock, shared by the copies in this process

 private:
  explicit FolderLock(std::shared_ptr<Held> held) : held_(std::move(held)) {}
  std::shared_ptr<Held> held_;
};

/// Takes the locks of every folder in `folders` (duplicates allowed), always in one order (sorted
/// paths) so that two processes locking overlapping sets cannot deadlock.
Result<std::vector<FolderLock>> lock_folders(std::vector<std::filesystem::path> folders);

}  // namespace shatter
