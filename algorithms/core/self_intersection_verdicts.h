#pragma once
/// The clean verdicts of the self-intersection check, remembered by mesh fingerprint
/// (mesh_fingerprint.h) so that the same mesh is not tested twice.
///
/// Design note: the memory is an object its caller creates and passes to the fracturers
/// (FractureParams::verdicts), as a physics engine passes its world: what one run remembers is
/// visible in its code, and two runs with two memories never see each other's verdicts. A run that
/// breaks the same solid many times (a grid breaks the same pre-fracture in every cell of a row)
/// passes one memory to all of them; a caller that passes none gets every check run.

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

namespace shatter {

/// How many clean verdicts a SelfIntersectionVerdicts remembers unless told otherwise.
inline constexpr std::size_t kRememberedCleanMeshes = 64;

/// The fingerprints of the last `capacity` meshes found clean, oldest overwritten first. Thread-safe.
class SelfIntersectionVerdicts {
 public:
  /// A memory of `capacity` (>= 1) clean verdicts.
  explicit SelfIntersectionVerdicts(std::size_t capacity = kRememberedCleanMeshes);
  /// True when the mesh of `fingerprint` was found clean and is still remembered.
  [[nodiscard]] bool remembers(std::uint64_t fingerprint) const;
  /// Remembers that the mesh of `fingerprint` was found clean.
  void remember(std::uint64_t fingerprint);

 private:
  mutable std::mutex mutex_;
  std::vector<std::uint64_t> seen_;
  std::size_t count_ = 0;
  std::size_t next_ = 0;
};

}  // namespace shatter
