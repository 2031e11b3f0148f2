#pragma once
/// The on-disk cache of pre-fractures (DESIGN.md section 3: "an unchanged pre-fracture -> taken from
/// the cache").
///
/// Design note. The key is a 64-bit FNV-1a hash over everything that decides the fragments: the
/// solid's exact bytes (vertices, triangles, face tags, attributes), the fracturer's name, the fragment count, the
/// seed and explicit planes, and the identity of the code that fractures: the commit plus the size
/// and modification time of the running executable, so a rebuild (even of uncommitted changes) never
/// reads an old answer. A file also stores its parameters and the solid's counts and is checked on
/// read, and ends with the FNV-1a hash of its bytes. A file that does not match, is truncated,
/// damaged (checksum), holds a non-finite number or an unknown face tag, is not a regular file, is
/// larger than kMaxCacheEntryBytes (checked before reading) or unreadable is a miss, never an error:
/// the pre-fracture is computed again and the entry replaced. Fragments
/// are stored bit for bit (vertices, mass properties and every attribute value as raw doubles;
/// material slots whole, an embedded image once per file however many fragments share it), so a
/// cached run is identical to a computed one. Files are written atomically; the folder is created on first use. A folder that
/// cannot be created or written disables the cache for the run (reported as a skip reason, not an
/// error: the cache is an optimisation).
///
/// Default folder: $SHATTERBENCH_CACHE, else $XDG_CACHE_HOME/shatterbench, else
/// $HOME/.cache/shatterbench.

#include "algorithms/core/mesh.h"
#include "algorithms/core/plane.h"
#include "algorithms/fracture/fracturer.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace shatter {

/// What a pre-fracture was asked for; with the solid it makes the cache key.
struct PrefractureKey {
  std::string fracturer;         ///< registered name (for explicit planes: the fracturer that cut them), then " " and its settings_text when it has settings
  int fragments = 0;             ///< requested count (0 for explicit planes)
  std::uint64_t seed = 0;        ///< seed (0 for explicit planes)
  std::vector<Plane> planes;     ///< explicit cuts, in order
};

/// A folder of cached pre-fractures.
class PrefractureCache {
 public:
  /// A cache in `folder` (created lazily).
  explicit PrefractureCache(std::filesystem::path folder);
  /// The default folder (see the file comment); empty when no environment variable gives one.
  static std::filesystem::path default_folder();

  /// The fragments stored for (`solid`, `key`), or nothing on a miss.
  [[nodiscard]] std::optional<std::vector<Fragment>> load(const Mesh& solid, const PrefractureKey& key) const;
  /// Stores `fragments` for (`solid`, `key`). False when the folder or file cannot be written.
  bool store(const Mesh& solid, const PrefractureKey& key, std::span<const Fragment> fragments) const;

  /// The folder.
  [[nodiscard]] const std::filesystem::path& folder() const { return folder_; }
  /// The file that holds (`solid`, `key`).
  [[nodiscard]] std::filesystem::path file_for(const Mesh& solid, const PrefractureKey& key) const;

 private:
  std::filesystem::path folder_;
};

/// The 16-hex-digit cache key of (`solid`, `key`) for this executable.
std::string prefracture_cache_key(const Mesh& solid, const PrefractureKey& key);

}  // namespace shatter
