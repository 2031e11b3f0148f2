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

/// An upper bound of the volume of the smaller side of `mesh` (inside `box`) cut by `plane`: the side
/// lies in the slab between the plane and its farthest vertex, and every section of the box by a plane
/// of normal n fits in the box's shadow on that plane, of area sum |n_k| (product of the other sides).
double smaller_side_bound(const Mesh& mesh, const Aabb& box, const Plane& plane) {
  const Vec3 n = plane.normal.normalized();
  double lo = 0.0;
  double hi = 0.0;
  for (const Vec3& v : mesh.vertices) {
    const double d = n.dot(v - plane.point);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  const Vec3 side = box.max - box.min;
  const double shadow = std::abs(n.x()) * side.y() * side.z() + std::abs(n.y()) * side.x() * side.z() +
                        std::abs(n.z()) * side.x() * side.y();
  // A plane with every vertex on one side (in double) likely leaves the piece whole: last.
  if (hi <= 0.0 || lo >= 0.0) return INFINITY;
  return std::min(hi, -lo) * shadow;
}

}  // namespace

PieceCounter::PieceCounter(const Mesh& solid, CornerProvenance* provenance) : kernel_(provenance) {
  std::vector<SliceKernel::Piece> start = start_pieces(solid, provenance);
  order_parts(kernel_, start);
  for (SliceKernel::Piece& piece : start) append(std::move(piece));
}

void PieceCounter::append(SliceKernel::Piece&& piece) {
  boxes_.push_back(bounding_box(piece.mesh));
  pieces_.push_back(std::move(piece));
}

int PieceCounter::add(const Plane& plane, double min_volume) {
  // Cut first, commit only when no part is a sliver: pieces the plane misses are never copied.
  std::vector<std::size_t> crossed;
  for (std::size_t i = 0; i < pieces_.size(); ++i)
    if (!misses(boxes_[i], plane)) crossed.push_back(i);
  // Any sliver rejects the plane, whichever piece it comes from; so the pieces most likely to give
  // one are cut first (a rejected plane then costs about one cut, not one per piece it crosses).
  if (min_volume > 0.0 && crossed.size() > 1) {
    std::vector<double> bound(pieces_.size());
    for (const std::size_t i : crossed) bound[i] = smaller_side_bound(pieces_[i].mesh, boxes_[i], plane);
    std::stable_sort(crossed.begin(), crossed.end(), [&](std::size_t a, std::size_t b) { return bound[a] < bound[b]; });
  }
  std::vector<std::pair<std::size_t, std::vector<SliceKernel::Piece>>> cuts;
  std::vector<SliceKernel::Piece> below;
  std::vector<SliceKernel::Piece> above;
  for (const std::size_t i : crossed) {
    below.clear();
    above.clear();
    kernel_.split(pieces_[i], plane, below, above);
    if (below.empty() || above.empty()) continue;
    if (min_volume > 0.0) {
      for (const std::vector<SliceKernel::Piece>* side : {&below, &above})
        for (const SliceKernel::Piece& part : *side)
          if (part.shape.volume < min_volume) return 0;  // the sum signed_volume takes
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
  std::sort(cuts.begin(), cuts.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
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
