#pragma once
/// What a game asset carries besides positions: per-corner normals, UV sets and tangent frames, and a
/// material slot per face.
///
/// Design note: attributes are stored per triangle corner, not per vertex. A UV seam or a hard edge
/// gives one position two attribute values; per-corner storage keeps the position welded (one vertex
/// index), so closedness, orientation, volumes and bonds are decided on positions alone and a seam is
/// never a boundary. Every attribute channel is linear: a corner made where a cut crosses an edge gets
/// each channel interpolated at the parameter used for its position, and normals and tangents are not
/// renormalised there (a renderer normalises them per pixel; the writers normalise them on output), so
/// a fragment's surface reproduces the input's interpolated attributes to round-off. A mesh without
/// attributes has every array here empty and pays no attribute work anywhere.

#include "algorithms/core/default_init_allocator.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace shatter {

/// Most UV sets one mesh may carry (glTF viewers read TEXCOORD_0 and TEXCOORD_1; assimp up to 8).
inline constexpr int kMaxUvSets = 4;

/// Most values one corner may hold (a normal, kMaxUvSets UV sets and a tangent).
inline constexpr int kMaxCornerValues = 3 + 2 * kMaxUvSets + 4;

/// Which channels each corner holds, in this order: normal (3), UV sets (2 each), tangent (4: a unit
/// direction and the bitangent's handedness, +1 or -1, as in glTF).
struct AttributeLayout {
  bool normals = false;  ///< a normal per corner
  int uv_sets = 0;       ///< 0..kMaxUvSets UV sets per corner
  bool tangents = false; ///< a tangent frame per corner (needs normals)

  /// Offset of the normal in a corner's values.
  [[nodiscard]] static constexpr int normal_offset() { return 0; }
  /// Offset of UV set `set` in a corner's values.
  [[nodiscard]] constexpr int uv_offset(int set) const { return (normals ? 3 : 0) + 2 * set; }
  /// Offset of the tangent in a corner's values.
  [[nodiscard]] constexpr int tangent_offset() const { return uv_offset(uv_sets); }
  /// Values per corner.
  [[nodiscard]] constexpr int stride() const { return tangent_offset() + (tangents ? 4 : 0); }
  /// True when corners carry nothing.
  [[nodiscard]] constexpr bool empty() const { return stride() == 0; }
  bool operator==(const AttributeLayout&) const = default;
};

/// An image carried inside an asset (a glTF binary's texture), shared by every mesh cut from it.
struct TextureImage {
  std::string mime_type;            ///< "image/png" or "image/jpeg"
  std::vector<std::uint8_t> bytes;  ///< the encoded image
};

/// One material of a mesh: what a renderer needs to draw its faces (a glTF metallic-roughness base).
struct MaterialSlot {
  std::string name;                                      ///< as the input named it (unique within a mesh)
  std::array<double, 4> base_color{1.0, 1.0, 1.0, 1.0};  ///< linear RGBA, each in [0, 1]
  std::string base_color_texture;  ///< image file as the input named it, relative to the input's folder; empty: none
  std::shared_ptr<const TextureImage> base_color_image;  ///< the image itself when the input embedded it
  bool operator==(const MaterialSlot&) const = default;
};

/// How a fracture dresses the faces it makes (cut faces): the interior material and a planar UV
/// projection (attribute_transfer.h, cut_face_corner).
struct CutFaceStyle {
  std::int32_t material = -1;  ///< slot of the interior material; -1 until prepare_cut_faces adds it
  double uv_scale = 0.0;       ///< metres per UV unit on cut faces (> 0 once prepared)
  bool operator==(const CutFaceStyle&) const = default;
};

/// Corner values: a std::vector<double> whose `resize` does not zero what it adds
/// (default_init_allocator.h: whoever grows it writes every new value).
using CornerValues = std::vector<double, DefaultInitAllocator<double>>;

/// The attributes of a mesh. Invariants (check_attributes): `corners.size() == 3 #F stride`;
/// `materials` is empty when `slots` is, and otherwise holds #F indices into `slots`.
struct MeshAttributes {
  AttributeLayout layout;               ///< channels per corner
  CornerValues corners;                 ///< corner k of triangle f at [(3 f + k) stride, (3 f + k + 1) stride)
  std::vector<std::int32_t> materials;  ///< #F material slots, or empty
  std::vector<MaterialSlot> slots;      ///< the materials, or empty
  CutFaceStyle cut;                     ///< how cut faces are dressed

  /// True when the mesh carries no attribute at all (then every fracture stays geometry only).
  [[nodiscard]] bool empty() const { return layout.empty() && slots.empty() && materials.empty(); }
  /// Values of corner `k` of triangle `f`.
  [[nodiscard]] const double* corner(std::size_t f, int k) const {
    return corners.data() + (3 * f + static_cast<std::size_t>(k)) * static_cast<std::size_t>(layout.stride());
  }
  bool operator==(const MeshAttributes&) const = default;
};

}  // namespace shatter
