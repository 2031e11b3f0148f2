#pragma once
/// The recursive plane-slicing schedule (seed section 8.1, after OpenFracture), written once over a
/// slicing kernel so that the fast kernel (plane-slice) and the exact reference (cgal-clip) make the
/// very same cuts and return fragments in the same order.
///
/// Design note: every decision of the schedule is taken so that two kernels whose geometry differs by
/// round-off still take the same branch. Pieces are cut first-in first-out (breadth first, which keeps
/// fragment sizes even) instead of "largest first": a plane through the centre of a symmetric solid
/// gives two halves of equal volume, and comparing those volumes would be decided by round-off. The
/// only geometric inputs are a piece's centroid (the cut plane goes through it, so both sides are
/// non-empty) and the order of the connected parts a cut leaves, sorted along a fixed generic
/// direction. One random normal is drawn per cut, whatever the kernel.
///
/// A kernel provides:
///   using Piece = ...;                                         // one connected closed solid
///   Vec3 centroid(const Piece&) const;                         // m
///   void split(const Piece&, const Plane&, std::vector<Piece>& below, std::vector<Piece>& above) const;
///     // appends the connected parts on each side; leaves at least one side empty when the plane
///     // does not cut the piece in two

#include "algorithms/core/plane.h"
#include "algorithms/core/random.h"
#include "algorithms/core/result.h"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace shatter {

/// The direction along which the parts of one cut are ordered; generic, so ties need a symmetric
/// solid placed exactly along it.
inline const Vec3& part_order_direction() {
  static const Vec3 d = Vec3(0.5773502691896258, 0.3183098861837907, 0.7071067811865476).normalized();
  return d;
}

/// Sorts the parts of one side of a cut along part_order_direction().
template <class Kernel>
void order_parts(const Kernel& kernel, std::vector<typename Kernel::Piece>& parts) {
  if (parts.size() < 2) return;
  std::vector<std::pair<double, std::size_t>> keys;
  keys.reserve(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i)
    keys.emplace_back(kernel.centroid(parts[i]).dot(part_order_direction()), i);
  std::stable_sort(keys.begin(), keys.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<typename Kernel::Piece> sorted;
  sorted.reserve(parts.size());
  for (const auto& key : keys) sorted.push_back(std::move(parts[key.second]));
  parts = std::move(sorted);
}

/// Cuts `start` (connected closed pieces) by random planes through each piece's centroid, first in
/// first out, until there are at least `fragments` pieces (a cut that leaves several parts on one side
/// can overshoot). Deterministic in `seed`.
template <class Kernel>
std::vector<typename Kernel::Piece> slice_recursively(const Kernel& kernel,
                                                      std::vector<typename Kernel::Piece> start,
                                                      int fragments, std::uint64_t seed) {
  using Piece = typename Kernel::Piece;
  order_parts(kernel, start);
  std::deque<Piece> queue(std::make_move_iterator(start.begin()), std::make_move_iterator(start.end()));
  std::vector<Piece> finished;  // pieces no plane through the centroid could cut (zero volume)
  SplitMix64 rng(seed);
  std::vector<Piece> below;
  std::vector<Piece> above;
  while (!queue.empty() && static_cast<int>(queue.size() + finished.size()) < fragments) {
    Piece piece = std::move(queue.front());
    queue.pop_front();
    const Plane plane{kernel.centroid(piece), rng.unit_vector()};
    below.clear();
    above.clear();
    kernel.split(piece, plane, below, above);
    if (below.empty() || above.empty()) {
      finished.push_back(std::move(piece));
      continue;
    }
    order_parts(kernel, below);
    order_parts(kernel, above);
    for (Piece& p : below) queue.push_back(std::move(p));
    for (Piece& p : above) queue.push_back(std::move(p));
  }
  std::vector<Piece> out;
  out.reserve(queue.size() + finished.size());
  for (Piece& p : queue) out.push_back(std::move(p));
  for (Piece& p : finished) out.push_back(std::move(p));
  return out;
}

/// Cuts every piece by every plane in turn (explicit pre-fracture cuts): a piece the plane misses is
/// kept whole. n planes can make far more than n + 1 pieces (a convex solid up to about n^3 / 6), so
/// the cut stops with an error as soon as there are more than `max_pieces`.
template <class Kernel>
Result<std::vector<typename Kernel::Piece>> slice_by_planes(const Kernel& kernel,
                                                            std::vector<typename Kernel::Piece> pieces,
                                                            std::span<const Plane> planes, std::size_t max_pieces) {
  using Piece = typename Kernel::Piece;
  order_parts(kernel, pieces);
  std::vector<Piece> below;
  std::vector<Piece> above;
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const Plane& plane = planes[k];
    if (pieces.size() > max_pieces)
      return Error{"the planes cut the solid into more than " + std::to_string(max_pieces) + " pieces (after " +
                   std::to_string(k) + " of " + std::to_string(planes.size()) +
                   " planes), which exceeds the limit of " + std::to_string(max_pieces) + " fragments"};
    std::vector<Piece> next;
    next.reserve(pieces.size() * 2);
    for (Piece& piece : pieces) {
      below.clear();
      above.clear();
      kernel.split(piece, plane, below, above);
      if (below.empty() || above.empty()) {
        next.push_back(std::move(piece));
        continue;
      }
      order_parts(kernel, below);
      order_parts(kernel, above);
      for (Piece& p : below) next.push_back(std::move(p));
      for (Piece& p : above) next.push_back(std::move(p));
    }
    pieces = std::move(next);
  }
  if (pieces.size() > max_pieces)
    return Error{"the planes cut the solid into " + std::to_string(pieces.size()) +
                 " pieces, which exceeds the limit of " + std::to_string(max_pieces) + " fragments"};
  return pieces;
}

}  // namespace shatter
