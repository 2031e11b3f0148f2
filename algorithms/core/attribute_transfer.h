#pragma once
/// Keeping a mesh's per-corner attributes (mesh_attributes.h) in step with its triangles: copying a
/// triangle with its corners, mixing corners where a cut crosses an edge, dressing cut faces, and
/// checking that a mesh's attributes are consistent. Every function here does nothing beyond the
/// geometry when the mesh carries no attributes.
///
/// Cut faces: the normal is the cut plane's outward unit normal. Every UV set gets the planar
/// projection u = (p . e1) / s, v = (p . e2) / s, where s is the style's `uv_scale` (metres per UV
/// unit) and (e1, e2) is an orthonormal basis of the plane built from the plane's canonical normal:
/// the one of +n, -n whose largest-magnitude component is positive (Duff et al. 2017, "Building an
/// orthonormal basis, revisited"). Both faces of one crack therefore get the same UV at the same point,
/// so an interior texture continues across the crack. The tangent is e1 with handedness +1 on the
/// canonical side and -1 on the other (bitangent = cross(normal, tangent) * w = e2 on both). The
/// material is the style's interior slot.

#include "algorithms/core/mesh.h"
#include "algorithms/core/result.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace shatter {

/// True when `mesh` carries attributes.
[[nodiscard]] inline bool has_attributes(const Mesh& mesh) { return !mesh.attributes.empty(); }

/// Gives `dst` the layout, material slots and cut-face style of `src`, with no per-face values (call
/// before appending `src`'s triangles to an empty mesh).
void copy_attribute_frame(const Mesh& src, Mesh& dst);

/// Appends triangle (a, b, c) of `dst` with the tag, material and corner values of triangle `f` of
/// `src`; new corner i takes corner `order[i]` of `f` (the default keeps them; {0, 2, 1} reverses).
void add_triangle_from(Mesh& dst, const Mesh& src, std::size_t f, std::int32_t a, std::int32_t b, std::int32_t c,
                       const std::array<int, 3>& order = {0, 1, 2});

/// One corner of a triangle that a cut made: corner `from` of the source triangle mixed towards its
/// corner `to` at parameter `t` (the value is from + t (to - from), channel by channel; `t` is the
/// parameter the position was made with). An original corner is {k, k, 0}.
struct CornerMix {
  int from = 0;    ///< corner of the source triangle, 0..2
  int to = 0;      ///< corner of the source triangle, 0..2
  double t = 0.0;  ///< in [0, 1]
};

/// Appends triangle (a, b, c) of `dst` cut from triangle `f` of `src`: its tag and material, and each
/// corner's values mixed as `mix` says.
void add_triangle_mixed(Mesh& dst, const Mesh& src, std::size_t f, std::int32_t a, std::int32_t b, std::int32_t c,
                        const std::array<CornerMix, 3>& mix);

/// Barycentric weights of a point over the three corners of its source triangle (they sum to 1).
using CornerWeights = std::array<double, 3>;

/// Appends triangle (a, b, c) of `dst` cut from triangle `f` of `src`: its tag and material, and
/// corner i's values as the weighted sum of `f`'s corner values by `weights[i]` (for a corner made by
/// several cuts in turn, whose weights follow from the parameters its position was made with).
void add_triangle_weighted(Mesh& dst, const Mesh& src, std::size_t f, std::int32_t a, std::int32_t b, std::int32_t c,
                           const std::array<CornerWeights, 3>& weights);

/// Appends the cut face (a, b, c) of `dst` (tag cut): when `dst` carries attributes, its corners are
/// dressed by `dst`'s cut-face style with `outward_normal` (any non-zero length) as the plane normal.
void add_cut_triangle(Mesh& dst, std::int32_t a, std::int32_t b, std::int32_t c, const Vec3& outward_normal);

/// Writes to `out` (3 x stride values of `layout`) the corners of a planar face with normal `normal`
/// at positions `p`, UVs at `scale` metres per unit: the cut-face dressing of the file comment.
void write_planar_corners(const AttributeLayout& layout, const Vec3& normal, const std::array<Vec3, 3>& p, double scale,
                          double* out);

/// The dressing of write_planar_corners prepared once for one plane and written for many of its
/// faces (a fracture dresses every cap face of a cut with one normal): each corner's normal and
/// tangent are fixed, only its UVs depend on where it is. The values are write_planar_corners'.
class PlanarDressing {
 public:
  /// The dressing of faces with normal `normal` (any non-zero length) in `layout`, UVs at `scale`
  /// metres per unit.
  PlanarDressing(const AttributeLayout& layout, const Vec3& normal, double scale);

  /// Writes to `out` (3 x stride values) the corners of the face with positions `a`, `b`, `c`.
  void write(const Vec3& a, const Vec3& b, const Vec3& c, double* out) const;

  /// Writes to `out` (3 x stride values a face) the corners of faces [first, first + count) of `mesh`,
  /// as write does face by face.
  void write_faces(const Mesh& mesh, std::size_t first, std::size_t count, double* out) const;

  /// The dressing of the faces with the opposite normal (the crack's other face): the same plane basis
  /// (cut_plane_basis), the normal and the tangent's handedness negated. Equal, value for value, to
  /// the dressing built for the negated normal (negation and normalisation commute exactly).
  [[nodiscard]] PlanarDressing reversed() const;

 private:
  std::array<double, kMaxCornerValues> fixed_{};  // one corner's normal and tangent at their offsets
  Vec3 e1_ = Vec3::UnitX();                 // the plane's basis (cut_plane_basis)
  Vec3 e2_ = Vec3::UnitY();
  double scale_ = 1.0;
  int stride_ = 0;
  int uv_offset_ = 0;
  int uv_sets_ = 0;
  int tangent_offset_ = 0;
  bool normals_ = false;
  bool tangents_ = false;
};

/// The dressing add_cut_triangle gives cut faces of `attr` with `outward_normal` (any non-zero length):
/// `attr`'s layout and cut-face UV scale (1 while the style is not prepared).
[[nodiscard]] PlanarDressing cut_face_dressing(const MeshAttributes& attr, const Vec3& outward_normal);

/// Orthonormal basis (e1, e2) of the plane with normal `normal`, built from its canonical normal (see
/// the file comment): the same basis for `normal` and `-normal`.
[[nodiscard]] std::array<Vec3, 2> cut_plane_basis(const Vec3& normal);

/// The cut-face UV of point `p` on a plane with normal `normal` (metres to UV by `uv_scale`).
[[nodiscard]] Vec2 cut_face_uv(const Vec3& p, const Vec3& normal, double uv_scale);

/// The cut-face UV scale used when neither the case nor a flag sets one: the largest side of the
/// mesh's bounding box, so the interior texture spans the solid once (1 for an empty mesh).
[[nodiscard]] double default_cut_uv_scale(const Mesh& mesh);

/// Readies an attributed mesh for fracture: adds the interior material slot after the mesh's own
/// slots (`interior` when given, else one named "interior", mid grey; the name gets a suffix "_2",
/// "_3", ... when the mesh already has a slot of that name), giving every face the slot "default"
/// first when the mesh has none, and sets the cut-face UV scale (`uv_scale` > 0, or
/// default_cut_uv_scale when 0). Does nothing to a mesh without attributes. Calling it again only
/// updates the scale.
void prepare_cut_faces(Mesh& mesh, double uv_scale = 0.0, const MaterialSlot* interior = nullptr);

/// Reverses every triangle's corner values in step with swapping each triangle's second and third
/// index (a whole-mesh orientation flip).
void reverse_corner_order(Mesh& mesh);

/// Keeps the triangles whose `keep` entry is non-zero, with their tags and attributes, in order.
void keep_triangles(Mesh& mesh, const std::vector<std::uint8_t>& keep);

/// Writes to `out` (layout stride values) triangle `f`'s corner values weighted by `weights` (one
/// weight per corner, e.g. barycentric coordinates).
void interpolate_corners(const MeshAttributes& attributes, std::size_t f, const Vec3& weights, double* out);

/// Gives `to` (a mesh made from `from` by repair: its faces lie on `from`'s, or were added and tagged
/// FaceTag::repair) `from`'s attribute frame and per-face values. A face that is not a repair face
/// takes, at each corner, the values of the nearest `from` triangle at that corner's barycentric
/// coordinates, and that triangle's material. A repair face is dressed as a cut face with its own
/// geometric normal (attribute_transfer.h's planar projection), in the material of the `from`
/// triangle nearest its centroid: a patched hole looks like the surface around it. Does nothing when
/// `from` has no attributes.
void transfer_attributes(const Mesh& from, Mesh& to);

/// Which of an attributed mesh's corner values check_attributes reads.
enum class AttributeValues {
  checked,  ///< every value must be finite (one pass over them)
  at_use,   ///< not read here: the caller checks each value where it reads it (CornerProvenance::resolve)
};

/// Checks the invariants of mesh_attributes.h, that every value is finite (unless `values` is
/// at_use), at most kMaxUvSets UV sets, tangents only with normals, and a prepared cut-face style
/// (interior slot in range, scale > 0) on an attributed mesh. The error names `who` and the first
/// offending triangle.
Status check_attributes(const Mesh& mesh, const std::string& who, AttributeValues values = AttributeValues::checked);

/// True when each of the `count` values at `values` is finite (one branch-free pass).
[[nodiscard]] bool all_finite(const double* values, std::size_t count);

/// Whether every value passed to it was finite, tallied as values are written (so a writer checks
/// its output without reading it again): v - v is 0 for a finite v and NaN otherwise, summed in 8
/// independent lanes that the compiler vectorises.
class FiniteTally {
 public:
  /// Copies `count` values from `from` to `to` (not overlapping) and tallies them.
  void copy(const double* from, std::size_t count, double* to);
  /// Tallies `count` values.
  void add(const double* values, std::size_t count);
  /// True when every value tallied so far was finite.
  [[nodiscard]] bool all_finite() const;

 private:
  std::array<double, 8> lanes_{};
};

/// True when every corner value a fracture of `solid` can make is finite, decided from two bounds on
/// the solid alone (one pass over its values, one over its positions), so that the fracture need not
/// look at its output: its values are each within a quarter of the largest double, and its largest
/// coordinate over its cut-face UV scale within a sixteenth. A fracture's values are the solid's
/// values copied, weighted sums of one solid face's three values whose weights are convex
/// combinations made by lerps at parameters in [0, 1] (so at most about the largest value in
/// magnitude), and cut-face values: unit normals and tangents, and UVs that are a position's dot
/// product with a unit vector over the scale, every position lying in the solid's bounding box
/// (|u| <= 3 (1 + eps) max|coordinate| / scale). False for a value that is not finite.
[[nodiscard]] bool fracture_attributes_bounded(const Mesh& solid);

/// The second of fracture_attributes_bounded's bounds, on the positions only (one pass over them):
/// true when every cut-face value a fracture of `solid` can make is finite (its largest coordinate
/// over its cut-face UV scale within a sixteenth of the largest double).
[[nodiscard]] bool cut_face_values_bounded(const Mesh& solid);

/// Why a fracture refuses when its output has a corner value that is not finite although the solid's
/// values are finite: a weighted sum of values near the largest double, or a cut face's UV of a
/// position far out against a tiny UV scale.
inline constexpr const char* kAttributeOverflow =
    "a corner attribute overflows (the input's values, or its size against the cut-face UV scale, are too large)";

}  // namespace shatter
