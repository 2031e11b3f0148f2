#pragma once
/// A compact binary form of meshes, for what crosses a process or a run: the pre-fracture cache's
/// entries and the mesh an importer child hands back (harness/cases/isolated_import.h).
///
/// Design note: the reader trusts nothing it reads. Every count is checked against the bytes left
/// before anything is allocated, and a decoded mesh must be one the rest of the code may index: finite
/// coordinates, every index in range, one known tag per triangle, attribute arrays of the sizes the
/// layout and the triangles give with material indices in range and finite values. A failed check is `false`, never a crash, so a damaged cache entry or a child
/// that died half-way through its answer is simply not used. Texture images are written once per
/// set of meshes and referred to by index, as meshes cut from one asset share them.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"

#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace shatter {

/// Appends raw bytes of trivially copyable values (the machine's byte order: a cache and a child are
/// read on the machine that wrote them).
class BinaryWriter {
 public:
  /// Appends `v` as its bytes.
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  /// Appends `n` bytes at `p`.
  void bytes(const void* p, std::size_t n) { out_.append(static_cast<const char*>(p), n); }
  /// Appends a length (64 bit) and the characters.
  void text(const std::string& s) {
    value(static_cast<std::uint64_t>(s.size()));
    bytes(s.data(), s.size());
  }
  /// Everything written so far.
  [[nodiscard]] const std::string& data() const { return out_; }

 private:
  std::string out_;
};

/// Reads what a BinaryWriter wrote, with bounds checks; any overrun makes ok() false for good.
class BinaryReader {
 public:
  /// Reads `in`, which must outlive the reader.
  explicit BinaryReader(const std::string& in) : in_(in) {}
  /// The next value (zero once not ok()).
  template <class T>
  T value() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v{};
    bytes(&v, sizeof v);
    return v;
  }
  /// The next `n` bytes into `p`.
  void bytes(void* p, std::size_t n) {
    if (!ok_ || in_.size() - pos_ < n) {
      ok_ = false;
      return;
    }
    if (n == 0) return;  // an empty block may come with a null destination (an empty vector's data())
    std::memcpy(p, in_.data() + pos_, n);
    pos_ += n;
  }
  /// The next text (empty once not ok()).
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
  /// False after any overrun.
  [[nodiscard]] bool ok() const { return ok_; }
  /// True when every byte was read.
  [[nodiscard]] bool at_end() const { return pos_ == in_.size(); }
  /// Bytes not read yet.
  [[nodiscard]] std::size_t left() const { return in_.size() - pos_; }

 private:
  const std::string& in_;
  std::size_t pos_ = 0;
  bool ok_ = true;
};

/// The distinct embedded images of `meshes`' material slots, in order of first use.
std::vector<const TextureImage*> embedded_images(std::span<const Mesh* const> meshes);

/// Writes `images` (count, then each MIME type and bytes).
void write_images(BinaryWriter& w, const std::vector<const TextureImage*>& images);

/// Reads what write_images wrote; false on an overrun.
bool read_images(BinaryReader& r, std::vector<std::shared_ptr<const TextureImage>>& images);

/// Writes `mesh` (vertices, triangles, tags, attributes), its slots' images as indices into `images`
/// (which must hold every one of them).
void write_mesh(BinaryWriter& w, const Mesh& mesh, const std::vector<const TextureImage*>& images);

/// Reads what write_mesh wrote into `mesh`; false on an overrun, an image index out of range, or a
/// mesh that fails the checks of the design note.
bool read_mesh(BinaryReader& r, Mesh& mesh, const std::vector<std::shared_ptr<const TextureImage>>& images);

/// One mesh with its images, as one string.
std::string encode_mesh(const Mesh& mesh);

/// What encode_mesh wrote, or an error naming `what` when the bytes are not a whole, valid mesh.
Result<Mesh> decode_mesh(const std::string& bytes, const std::string& what);

}  // namespace shatter
