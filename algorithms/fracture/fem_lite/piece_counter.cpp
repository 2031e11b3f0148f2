#include "algorithms/fracture/fem_lite/piece_counter.h"

#include "algorithms/core/mass_properties.h"
#include "algorithms/fracture/recursive_slicing.h"

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
  std::vector<SliceKernel::Piece> start = start_pieces(solid, nullptr);
  order_parts(kernel_, start);
  for (SliceKernel::Piece& piece : start) append(std::move(piece));
}

void PieceCounter::append(SliceKernel::Piece&& piece) {
  boxes_.push_back(bounding_box(piece.mesh));
  pieces_.push_back(std::move(piece));
}

int PieceCounter::add(const Plane& plane, double min_volume) {
  // Cut first, commit only when no part is a sliver: pieces the plane misses are never copied.
  std::vector<std::pair<std::size_t, std::vector<SliceKernel::Piece>>> cuts;
  std::vector<SliceKernel::Piece> below;
  std::vector<SliceKernel::Piece> above;
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    if (misses(boxes_[i], plane)) continue;
    below.clear();
    above.clear();
    kernel_.split(pieces_[i], plane, below, above);
    if (below.empty() || above.empty()) continue;
    if (min_volume > 0.0) {
      for (const std::vector<SliceKernel::Piece>* side : {&below, &above})
        for (const SliceKernel::Piece& part : *side)
          if (signed_volume(part.mesh) < min_volume) return 0;
    }
    // The order of slice_by_planes (recursive_slicing.h): each side's parts sorted, below first.
    order_parts(kernel_, below);
    order_parts(kernel_, above);
    std::vector<SliceKernel::Piece> parts;
    parts.reserve(below.size() + above.size());
    for (SliceKernel::Piece& part : below) parts.push_back(std::move(part));
    for (SliceKernel::Piece& part : above) parts.push_back(std::move(part));
    cuts.emplace_back(i, std::move(parts));
  }
  if (cuts.empty()) return 0;
  const int before = count();
  std::vector<SliceKernel::Piece> old_pieces = std::move(pieces_);
  std::vector<Aabb> old_boxes = std::move(boxes_);
  pieces_.clear();
  boxes_.clear();
  std::size_t next_cut = 0;
  for (std::size_t i = 0; i < old_pieces.size(); ++i) {
    if (next_cut < cuts.size() && cuts[next_cut].first == i) {
      for (SliceKernel::Piece& part : cuts[next_cut].second) append(std::move(part));
      ++next_cut;
      continue;
    }
    pieces_.push_back(std::move(old_pieces[i]));
    boxes_.push_back(old_boxes[i]);
  }
  return count() - before;
}

std::vector<SliceKernel::Piece> PieceCounter::take_pieces() {
  boxes_.clear();
  return std::move(pieces_);
}

}  // namespace shatter
