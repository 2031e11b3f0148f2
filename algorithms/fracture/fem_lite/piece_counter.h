#pragma once
/// The pieces that cutting a solid by a growing list of planes gives, exactly as
/// PlaneSliceFracturer::fracture_by_planes makes them (the same kernel on the same pieces, every piece
/// a plane crosses cut, disconnected parts split, the parts of each cut in the same order), so that
/// the pieces of the last plane are the fracture's fragments.

#include "algorithms/core/plane.h"
#include "algorithms/fracture/plane_slice/slice_kernel.h"

#include <vector>

namespace shatter {

/// The pieces of a solid under the planes added so far.
class PieceCounter {
 public:
  /// Starts from the connected parts of `solid` (closed, outward), cut as plain meshes, or with their
  /// corners tracked through `provenance` (an attributed solid's, as fracture_by_planes tracks them;
  /// it must outlive the counter). A plane the counter rejects leaves unused records in `provenance`.
  explicit PieceCounter(const Mesh& solid, CornerProvenance* provenance = nullptr);
  /// Cuts every current piece `plane` crosses; returns the number of pieces added (0: no change).
  /// When a part it cuts off has a volume below `min_volume` (m^3), the plane changes nothing.
  int add(const Plane& plane, double min_volume = 0.0);
  /// Current number of pieces.
  [[nodiscard]] int count() const { return static_cast<int>(pieces_.size()); }
  /// The pieces, in the order fracture_by_planes gives them; the counter is left empty.
  std::vector<SliceKernel::Piece> take_pieces();

 private:
  void append(SliceKernel::Piece&& piece);
  SliceKernel kernel_;
  std::vector<SliceKernel::Piece> pieces_;
  std::vector<Aabb> boxes_;  // bounding box of each piece, to skip the pieces a plane misses
};

}  // namespace shatter
