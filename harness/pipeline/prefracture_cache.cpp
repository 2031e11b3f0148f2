#include "harness/pipeline/prefracture_cache.h"

#include "harness/plugins/plugin_loader.h"

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
// version 3 stores each fragment's attributes and the solid's attributes are part of the key.
constexpr char kMagic[8] = {'S', 'B', 'P', 'F', 'R', 'A', 'C', '3'};

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

/// Appends raw bytes of trivially copyable values.
class Writer {
 public:
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  void bytes(const void* p, std::size_t n) { out_.append(static_cast<const char*>(p), n); }
  void text(const std::string& s) {
    value(static_cast<std::uint64_t>(s.size()));
    bytes(s.data(), s.size());
  }
  [[nodiscard]] const std::string& data() const { return out_; }

 private:
  std::string out_;
};

/// Reads raw values back with bounds checks; any overrun makes ok() false.
class Reader {
 public:
  explicit Reader(const std::string& in) : in_(in) {}
  template <class T>
  T value() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v{};
    bytes(&v, sizeof v);
    return v;
  }
  void bytes(void* p, std::size_t n) {
    if (!ok_ || in_.size() - pos_ < n) {
      ok_ = false;
      return;
    }
    if (n == 0) return;  // an empty block may come with a null destination (an empty vector's data())
    std::memcpy(p, in_.data() + pos_, n);
    pos_ += n;
  }
  std::string text() {
    const auto n = value<std::uint64_t>();
    if (!ok_ || n > left()) {
      ok_ = false;
      return {};
    }
    std::string s(static_cast<std::size_t>(n), '\0');
    bytes(s.data(), s.size());
    return s;
  }
  [[nodiscard]] bool ok() const { return ok_; }
  [[nodiscard]] bool at_end() const { return pos_ == in_.size(); }
  [[nodiscard]] std::size_t left() const { return in_.size() - pos_; }

 private:
  const std::string& in_;
  std::size_t pos_ = 0;
  bool ok_ = true;
};

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

/// The distinct embedded images of the fragments' slots, in order of first use: stored once per file,
/// since every fragment cut from one mesh shares them.
std::vector<const TextureImage*> images_of(std::span<const Fragment> fragments) {
  std::vector<const TextureImage*> images;
  for (const Fragment& f : fragments)
    for (const MaterialSlot& slot : f.mesh.attributes.slots)
      if (slot.base_color_image && std::find(images.begin(), images.end(), slot.base_color_image.get()) == images.end())
        images.push_back(slot.base_color_image.get());
  return images;
}

/// Appends a mesh's attributes; slot images as indices into `images`.
void write_attributes(Writer& w, const MeshAttributes& a, const std::vector<const TextureImage*>& images) {
  w.value(static_cast<std::uint8_t>(a.layout.normals));
  w.value(static_cast<std::int32_t>(a.layout.uv_sets));
  w.value(static_cast<std::uint8_t>(a.layout.tangents));
  w.value(static_cast<std::uint64_t>(a.corners.size()));
  w.bytes(a.corners.data(), a.corners.size() * sizeof(double));
  w.value(static_cast<std::uint64_t>(a.materials.size()));
  w.bytes(a.materials.data(), a.materials.size() * sizeof(std::int32_t));
  w.value(static_cast<std::uint64_t>(a.slots.size()));
  for (const MaterialSlot& slot : a.slots) {
    w.text(slot.name);
    w.bytes(slot.base_color.data(), sizeof slot.base_color);
    w.text(slot.base_color_texture);
    const auto image = std::find(images.begin(), images.end(), slot.base_color_image.get());
    w.value(slot.base_color_image ? static_cast<std::int64_t>(image - images.begin()) : std::int64_t{-1});
  }
  w.value(a.cut.material);
  w.value(a.cut.uv_scale);
}

/// Reads what write_attributes wrote; false on any overrun or an image index out of range.
bool read_attributes(Reader& r, MeshAttributes& a, const std::vector<std::shared_ptr<const TextureImage>>& images) {
  a.layout.normals = r.value<std::uint8_t>() != 0;
  a.layout.uv_sets = r.value<std::int32_t>();
  a.layout.tangents = r.value<std::uint8_t>() != 0;
  if (a.layout.uv_sets < 0 || a.layout.uv_sets > kMaxUvSets) return false;
  const auto corners = r.value<std::uint64_t>();
  if (!r.ok() || corners > r.left() / sizeof(double)) return false;
  a.corners.resize(static_cast<std::size_t>(corners));
  r.bytes(a.corners.data(), a.corners.size() * sizeof(double));
  const auto materials = r.value<std::uint64_t>();
  if (!r.ok() || materials > r.left() / sizeof(std::int32_t)) return false;
  a.materials.resize(static_cast<std::size_t>(materials));
  r.bytes(a.materials.data(), a.materials.size() * sizeof(std::int32_t));
  const auto slots = r.value<std::uint64_t>();
  if (!r.ok() || slots > r.left()) return false;
  a.slots.resize(static_cast<std::size_t>(slots));
  for (MaterialSlot& slot : a.slots) {
    slot.name = r.text();
    r.bytes(slot.base_color.data(), sizeof slot.base_color);
    slot.base_color_texture = r.text();
    const auto image = r.value<std::int64_t>();
    if (image < -1 || image >= static_cast<std::int64_t>(images.size())) return false;
    if (image >= 0) slot.base_color_image = images[static_cast<std::size_t>(image)];
  }
  a.cut.material = r.value<std::int32_t>();
  a.cut.uv_scale = r.value<double>();
  return r.ok();
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

/// Whether every number of `f` is finite and every tag one of FaceTag's values.
bool plausible(const Fragment& f) {
  for (const Vec3& v : f.mesh.vertices)
    if (!v.allFinite()) return false;
  for (const FaceTag t : f.mesh.tags)
    if (t != FaceTag::surface && t != FaceTag::cut && t != FaceTag::repair) return false;
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

  const auto image_count = r.value<std::uint64_t>();
  if (!r.ok() || image_count > r.left()) return std::nullopt;
  std::vector<std::shared_ptr<const TextureImage>> images;
  for (std::uint64_t i = 0; i < image_count && r.ok(); ++i) {
    auto image = std::make_shared<TextureImage>();
    image->mime_type = r.text();
    const std::string bytes = r.text();
    image->bytes.assign(bytes.begin(), bytes.end());
    images.push_back(std::move(image));
  }
  const auto count = r.value<std::uint64_t>();
  if (!r.ok() || count > r.left()) return std::nullopt;
  std::vector<Fragment> fragments(static_cast<std::size_t>(count));
  for (Fragment& f : fragments) {
    const auto nv = r.value<std::uint64_t>();
    const auto nt = r.value<std::uint64_t>();
    if (!r.ok() || nv > r.left() / (3 * sizeof(double)) || nt > r.left() / (3 * sizeof(std::int32_t))) return std::nullopt;
    f.mesh.vertices.resize(static_cast<std::size_t>(nv));
    f.mesh.triangles.resize(static_cast<std::size_t>(nt));
    f.mesh.tags.resize(static_cast<std::size_t>(nt));
    for (Vec3& v : f.mesh.vertices) r.bytes(v.data(), 3 * sizeof(double));
    for (Triangle& t : f.mesh.triangles) r.bytes(t.data(), 3 * sizeof(std::int32_t));
    r.bytes(f.mesh.tags.data(), f.mesh.tags.size() * sizeof(FaceTag));
    r.bytes(&f.mass.volume, sizeof(double));
    r.bytes(f.mass.centroid.data(), 3 * sizeof(double));
    r.bytes(f.mass.inertia.data(), 9 * sizeof(double));
    if (!read_attributes(r, f.mesh.attributes, images)) return std::nullopt;
    if (!r.ok() || !plausible(f)) return std::nullopt;
    if (!f.mesh.attributes.empty() && !check_attributes(f.mesh, "cache")) return std::nullopt;
    for (const Triangle& t : f.mesh.triangles)
      for (const std::int32_t i : t)
        if (i < 0 || static_cast<std::uint64_t>(i) >= nv) return std::nullopt;
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
  const std::vector<const TextureImage*> images = images_of(fragments);
  w.value(static_cast<std::uint64_t>(images.size()));
  for (const TextureImage* image : images) {
    w.text(image->mime_type);
    w.text(std::string(image->bytes.begin(), image->bytes.end()));
  }
  w.value(static_cast<std::uint64_t>(fragments.size()));
  for (const Fragment& f : fragments) {
    w.value(static_cast<std::uint64_t>(f.mesh.vertices.size()));
    w.value(static_cast<std::uint64_t>(f.mesh.triangles.size()));
    for (const Vec3& v : f.mesh.vertices) w.bytes(v.data(), 3 * sizeof(double));
    for (const Triangle& t : f.mesh.triangles) w.bytes(t.data(), 3 * sizeof(std::int32_t));
    w.bytes(f.mesh.tags.data(), f.mesh.tags.size() * sizeof(FaceTag));
    w.bytes(&f.mass.volume, sizeof(double));
    w.bytes(f.mass.centroid.data(), 3 * sizeof(double));
    w.bytes(f.mass.inertia.data(), 9 * sizeof(double));
    write_attributes(w, f.mesh.attributes, images);
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
