#include "algorithms/fracture/fem_lite/crack_plane_search.h"

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/random.h"
#include "algorithms/fracture/fem_lite/piece_counter.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace shatter {
namespace {

/// True when `centre` lies closer than `spacing` cells to one of `planes` (along its unit normal).
bool too_close(const Vec3& centre, std::span<const Plane> planes, const Vec3& cell, double spacing) {
  if (spacing <= 0.0) return false;
  for (const Plane& p : planes) {
    const Vec3 n = p.normal.normalized();
    const double width = cell.cwiseProduct(n).norm();  // the cell's size along n, m
    if (std::abs(n.dot(centre - p.point)) < spacing * width * (1.0 - 1e-9)) return true;
  }
  return false;
}

}  // namespace

CrackSearch search_crack_planes(const Mesh& solid, const HexGrid& grid, std::span<const ElementStress> stresses,
                                const CrackSearchOptions& options, std::vector<SliceKernel::Piece>* pieces_out,
                                CornerProvenance* provenance) {
  CrackSearch search;
  const std::size_t count = stresses.size();
  for (const ElementStress& s : stresses)
    if (s.max_principal > options.tensile_strength) ++search.over_strength;

  // Most stressed first; ties in element order.
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return stresses[a].max_principal > stresses[b].max_principal;
  });
  // An element without stress (no load reaches it) cracks in a random direction.
  SplitMix64 rng(options.seed);
  std::vector<Vec3> normals(count);
  for (std::size_t e = 0; e < count; ++e)
    normals[e] = stresses[e].direction.squaredNorm() > 0.0 ? stresses[e].direction : rng.unit_vector();

  PieceCounter pieces(solid, provenance);
  const double min_volume = options.min_piece_share * signed_volume(solid) / std::max(options.fragments, 1);
  std::vector<bool> tried(count, false);
  std::vector<bool> sliver(count, false);  // skipped for a sliver: tried again if the count is short
  const double spacing = options.spacing;
  for (double factor : {1.0, 0.5, 0.25, 0.0}) {
    if (pieces.count() >= options.fragments) break;
    if (factor > 0.0 && spacing == 0.0) continue;
    for (std::size_t e : order) {
      if (pieces.count() >= options.fragments) break;
      if (tried[e] || too_close(grid.centres[e], search.planes, grid.cell, factor * spacing)) continue;
      tried[e] = true;
      ++search.candidates_tried;
      const Plane plane{grid.centres[e], normals[e]};
      const int added = pieces.add(plane, min_volume);
      if (added > 0) search.planes.push_back(plane);
      sliver[e] = added == 0 && min_volume > 0.0;
    }
  }
  for (std::size_t e : order) {
    if (pieces.count() >= options.fragments) break;
    if (!sliver[e]) continue;
    ++search.candidates_tried;
    const Plane plane{grid.centres[e], normals[e]};
    if (pieces.add(plane) > 0) search.planes.push_back(plane);
  }
  search.fragments = pieces.count();
  if (pieces_out != nullptr) *pieces_out = pieces.take_pieces();
  return search;
}

}  // namespace shatter
