#pragma once
/// Counts the fragments that cutting a solid by a growing list of planes gives, exactly as
/// PlaneSliceFracturer::fracture_by_planes does (the same slicer on the same pieces, every piece a
/// plane crosses cut, disconnected parts split), without building fragments.

#include "algorithms/core/plane.h"
#include "algorithms/fracture/plane_slice/mesh_slicer.h"

#include <vector>

namespace shatter {

/// The pieces of a solid under the planes added so far.
class PieceCounter {
 public:
  /// Starts from the connected parts of `solid` (closed, outward).
  explicit PieceCounter(const Mesh& solid);
  /// Cuts every current piece `plane` crosses; returns the number of pieces added (0: no change).
  /// When a part it cuts off has a volume below `min_volume` (m^3), the plane changes nothing.
  int add(const Plane& plane, double min_volume = 0.0);
  /// Current number of pieces.
  [[nodiscard]] int count() const { return static_cast<int>(pieces_.size()); }

 private:
  void append(Mesh&& mesh);
  MeshSlicer slicer_;
  std::vector<Mesh> pieces_;
  std::vector<Aabb> boxes_;  // bounding box of each piece, to skip the pieces a plane misses
};

}  // namespace shatter
