#include "harness/pipeline/prefracture_cache.h"

#include "harness/plugins/plugin_loader.h"

#include "algorithms/assets/mesh_codec.h"
#include "algorithms/core/attribute_transfer.h"
#include "harness/limits.h"
#include "harness/output/atomic_file.h"

#include <fmt/core.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <cerrno>
#include <system_error>
#include <type_traits>

#if !defined(SHATTER_GIT_COMMIT)
#error "SHATTER_GIT_COMMIT must be defined by the build"
#endif

namespace shatter {
namespace {

// Version 2 ends every file with the FNV-1a hash of all bytes before it (a flipped bit is a miss);
// version 3 stores each fragment's attributes and the solid's attributes are part of the key; version
// 4 stores each fragment's mesh in the form of algorithms/assets/mesh_codec.h, then its mass.
constexpr char kMagic[8] = {'S', 'B', 'P', 'F', 'R', 'A', 'C', '4'};

/// FNV-1a, 64 bit, fed field by field.
class Fnv1a {
 public:
  void bytes(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) {
      hash_ ^= p[i];
      hash_ *= 0x100000001b3ULL;
    }
  }
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  void text(const std::string& s) {
    value(s.size());
    bytes(s.data(), s.size());
  }
  [[nodiscard]] std::uint64_t hash() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

/// The commit plus the running executable's size and modification time and the loaded plugins' (plugins
/// are loaded before any fracture): changes with every rebuild of either.
const std::string& code_identity() {
  static const std::string identity = [] {
    std::string id = SHATTER_GIT_COMMIT;
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
      const auto size = std::filesystem::file_size(exe, ec);
      if (!ec) id += fmt::format("/{}", size);
      const auto time = std::filesystem::last_write_time(exe, ec);
      if (!ec) id += fmt::format("/{}", time.time_since_epoch().count());
    }
    return id + "/" + loaded_plugins_identity();
  }();
  return identity;
}

std::uint64_t key_hash(const Mesh& solid, const PrefractureKey& key) {
  Fnv1a h;
  h.bytes(kMagic, sizeof kMagic);
  h.text(code_identity());
  h.value(solid.vertices.size());
  for (const Vec3& v : solid.vertices) h.bytes(v.data(), 3 * sizeof(double));
  h.value(solid.triangles.size());
  for (const Triangle& t : solid.triangles) h.bytes(t.data(), 3 * sizeof(std::int32_t));
  for (const FaceTag t : solid.tags) h.value(t);
  // The solid's attributes decide the fragments' attributes (an OBJ and its retextured copy differ).
  const MeshAttributes& a = solid.attributes;
  h.value(a.layout.normals);
  h.value(a.layout.uv_sets);
  h.value(a.layout.tangents);
  h.value(a.corners.size());
  h.bytes(a.corners.data(), a.corners.size() * sizeof(double));
  h.value(a.materials.size());
  h.bytes(a.materials.data(), a.materials.size() * sizeof(std::int32_t));
  h.value(a.slots.size());
  for (const MaterialSlot& slot : a.slots) {
    h.text(slot.name);
    h.bytes(slot.base_color.data(), sizeof slot.base_color);
    h.text(slot.base_color_texture);
    h.value(slot.base_color_image ? slot.base_color_image->bytes.size() : std::size_t{0});
    if (slot.base_color_image) h.bytes(slot.base_color_image->bytes.data(), slot.base_color_image->bytes.size());
  }
  h.value(a.cut.material);
  h.value(a.cut.uv_scale);
  h.text(key.fracturer);
  h.value(key.fragments);
  h.value(key.seed);
  h.value(key.planes.size());
  for (const Plane& p : key.planes) {
    h.bytes(p.point.data(), 3 * sizeof(double));
    h.bytes(p.normal.data(), 3 * sizeof(double));
  }
  return h.hash();
}

using Writer = BinaryWriter;
using Reader = BinaryReader;

void write_header(Writer& w, std::uint64_t hash, const Mesh& solid, const PrefractureKey& key) {
  w.bytes(kMagic, sizeof kMagic);
  w.value(hash);
  w.value(static_cast<std::uint64_t>(solid.vertices.size()));
  w.value(static_cast<std::uint64_t>(solid.triangles.size()));
  w.value(static_cast<std::int32_t>(key.fragments));
  w.value(key.seed);
  w.value(static_cast<std::uint64_t>(key.planes.size()));
  w.value(static_cast<std::uint64_t>(key.fracturer.size()));
  w.bytes(key.fracturer.data(), key.fracturer.size());
}

/// FNV-1a of `n` bytes at `data`: the checksum a cache file ends with.
std::uint64_t checksum(const char* data, std::size_t n) {
  Fnv1a h;
  h.bytes(data, n);
  return h.hash();
}

/// The bytes of the regular file at `path` when it holds at most kMaxCacheEntryBytes; nothing for a
/// missing, unreadable, larger or not regular file (a FIFO, a device, a folder, a link to one). The
/// size is checked before anything is allocated, and no more than it is read.
std::optional<std::string> read_entry(const std::filesystem::path& path) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below anyway.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return std::nullopt;
  struct stat st {};
  std::optional<std::string> out;
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size >= 0 &&
      static_cast<std::uint64_t>(st.st_size) <= kMaxCacheEntryBytes) {
    std::string data(static_cast<std::size_t>(st.st_size), '\0');
    std::size_t got = 0;
    while (got < data.size()) {
      const ssize_t n = ::read(fd, data.data() + got, data.size() - got);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      got += static_cast<std::size_t>(n);
    }
    char extra = 0;
    if (got == data.size() && ::read(fd, &extra, 1) == 0) out = std::move(data);  // not grown since fstat
  }
  ::close(fd);
  return out;
}

/// Whether the mass properties of `f` are finite (its mesh is checked by read_mesh).
bool plausible(const Fragment& f) {
  return std::isfinite(f.mass.volume) && f.mass.centroid.allFinite() && f.mass.inertia.allFinite();
}

}  // namespace

std::string prefracture_cache_key(const Mesh& solid, const PrefractureKey& key) {
  return fmt::format("{:016x}", key_hash(solid, key));
}

PrefractureCache::PrefractureCache(std::filesystem::path folder) : folder_(std::move(folder)) {}

std::filesystem::path PrefractureCache::default_folder() {
  if (const char* v = std::getenv("SHATTERBENCH_CACHE"); v != nullptr && *v != '\0') return v;
  if (const char* v = std::getenv("XDG_CACHE_HOME"); v != nullptr && *v != '\0')
    return std::filesystem::path(v) / "shatterbench";
  if (const char* v = std::getenv("HOME"); v != nullptr && *v != '\0')
    return std::filesystem::path(v) / ".cache" / "shatterbench";
  return {};
}

std::filesystem::path PrefractureCache::file_for(const Mesh& solid, const PrefractureKey& key) const {
  return folder_ / ("prefracture-" + prefracture_cache_key(solid, key) + ".bin");
}

std::optional<std::vector<Fragment>> PrefractureCache::load(const Mesh& solid, const PrefractureKey& key) const {
  if (folder_.empty()) return std::nullopt;
  // Any entry that cannot be read or fails a check is a miss: the run fractures again and store()
  // replaces the entry, so a damaged cache costs one recomputation, never a refused case.
  std::optional<std::string> file = read_entry(file_for(solid, key));
  if (!file || file->size() < sizeof(std::uint64_t)) return std::nullopt;
  std::uint64_t sum = 0;
  std::memcpy(&sum, file->data() + file->size() - sizeof sum, sizeof sum);
  file->resize(file->size() - sizeof sum);
  if (checksum(file->data(), file->size()) != sum) return std::nullopt;
  const std::string& data = *file;

  Writer expected;
  write_header(expected, key_hash(solid, key), solid, key);
  if (data.compare(0, expected.data().size(), expected.data()) != 0) return std::nullopt;
  Reader r(data);
  std::string skip(expected.data().size(), '\0');
  r.bytes(skip.data(), skip.size());

  std::vector<std::shared_ptr<const TextureImage>> images;
  if (!read_images(r, images)) return std::nullopt;
  const auto count = r.value<std::uint64_t>();
  if (!r.ok() || count > r.left()) return std::nullopt;
  std::vector<Fragment> fragments(static_cast<std::size_t>(count));
  for (Fragment& f : fragments) {
    if (!read_mesh(r, f.mesh, images)) return std::nullopt;
    r.bytes(&f.mass.volume, sizeof(double));
    r.bytes(f.mass.centroid.data(), 3 * sizeof(double));
    r.bytes(f.mass.inertia.data(), 9 * sizeof(double));
    if (!r.ok() || !plausible(f)) return std::nullopt;
    if (!f.mesh.attributes.empty() && !check_attributes(f.mesh, "cache")) return std::nullopt;
  }
  if (!r.ok() || !r.at_end()) return std::nullopt;
  return fragments;
}

bool PrefractureCache::store(const Mesh& solid, const PrefractureKey& key, std::span<const Fragment> fragments) const {
  if (folder_.empty()) return false;
  std::error_code ec;
  std::filesystem::create_directories(folder_, ec);
  if (ec) return false;
  Writer w;
  write_header(w, key_hash(solid, key), solid, key);
  std::vector<const Mesh*> meshes;
  for (const Fragment& f : fragments) meshes.push_back(&f.mesh);
  const std::vector<const TextureImage*> images = embedded_images(meshes);
  write_images(w, images);
  w.value(static_cast<std::uint64_t>(fragments.size()));
  for (const Fragment& f : fragments) {
    write_mesh(w, f.mesh, images);
    w.bytes(&f.mass.volume, sizeof(double));
    w.bytes(f.mass.centroid.data(), 3 * sizeof(double));
    w.bytes(f.mass.inertia.data(), 9 * sizeof(double));
  }
  const std::uint64_t sum = checksum(w.data().data(), w.data().size());
  w.value(sum);
  if (w.data().size() > kMaxCacheEntryBytes) return false;  // it could not be read back
  // The folder is the cache's own: an entry that is not a regular file (a folder, a FIFO, a link left
  // there) was a miss, and goes, so that the rename below can put the computed entry in its place.
  const std::filesystem::path file = file_for(solid, key);
  const std::filesystem::file_status status = std::filesystem::symlink_status(file, ec);
  if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    std::filesystem::remove_all(file, ec);
  return static_cast<bool>(write_file_atomically(file, w.data()));
}

}  // namespace shatter
