#include "algorithms/fracture/fem_lite/piece_counter.h"

#include "algorithms/core/mesh_components.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace shatter {
namespace {

/// True when every corner of `box` is clearly on one side of `plane` (so every vertex is, and the
/// slicer would leave the piece whole).
bool misses(const Aabb& box, const Plane& plane) {
  double lo = INFINITY;
  double hi = -INFINITY;
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner((c & 1) ? box.max.x() : box.min.x(), (c & 2) ? box.max.y() : box.min.y(),
                      (c & 4) ? box.max.z() : box.min.z());
    const double s = plane.normal.dot(corner - plane.point);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  const double margin = 1e-9 * plane.normal.norm() * (box.diagonal() + (box.min - plane.point).norm());
  return lo > margin || hi < -margin;
}

}  // namespace

PieceCounter::PieceCounter(const Mesh& solid) {
  for (Mesh& part : connected_components(Mesh(solid))) append(std::move(part));
}

void PieceCounter::append(Mesh&& mesh) {
  boxes_.push_back(bounding_box(mesh));
  pieces_.push_back(std::move(mesh));
}

int PieceCounter::add(const Plane& plane) {
  const int before = count();
  std::vector<Mesh> old_pieces = std::move(pieces_);
  std::vector<Aabb> old_boxes = std::move(boxes_);
  pieces_.clear();
  boxes_.clear();
  Mesh below;
  Mesh above;
  for (std::size_t i = 0; i < old_pieces.size(); ++i) {
    if (misses(old_boxes[i], plane) || slicer_.slice(old_pieces[i], plane, below, above) != SliceOutcome::cut) {
      pieces_.push_back(std::move(old_pieces[i]));
      boxes_.push_back(old_boxes[i]);
      continue;
    }
    for (Mesh* half : {&below, &above})
      for (Mesh& part : connected_components(std::move(*half))) append(std::move(part));
  }
  return count() - before;
}

}  // namespace shatter
