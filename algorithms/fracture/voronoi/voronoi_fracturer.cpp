// Design note: each cell is first cut by CellClipper (cell_clipper.h), one pass over the triangles
// near the cell. The cells it cannot decide go to the sequential path below (CellCutter).
//
// The sequential path: the cost of clipping with MeshSlicer is the size of the piece it is given, whether the
// plane cuts off much or little. Cutting every cell out of the whole solid would cost #cells whole-
// mesh passes. Only bisector planes may leave faces on a cell, but any plane that keeps a cell whole
// on one side may shrink the piece the cell is cut from: its cap lies outside the cell and the
// bisectors cut it away. So the sites are split recursively into two halves along the longest axis
// (a kd-tree), and each half gets the piece cut by the axis plane that bounds the union of its cells
// (VoronoiCell::bounds, inflated so that round-off cannot put a cell across it). A tree cut within
// round-off of the piece's extent is skipped: it would re-cut the rounded points of an earlier cut at
// the same place. At a leaf, the cell is cut from that small piece by its bisectors in greedy order:
// each step takes the bisector that a double-precision count says removes the most vertices, and
// drops bisectors that clearly miss the piece (they miss every later, smaller piece too); only
// bisectors within twice the cell's reach are candidates. A bisector that leaves nothing on the
// site's side means the cell misses the solid: the cell is dropped at that point.

#include "algorithms/fracture/voronoi/voronoi_fracturer.h"

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_assembly.h"
#include "algorithms/core/volume_components.h"
#include "algorithms/core/representable_range.h"
#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/fracture/plane_slice/mesh_slicer.h"
#include "algorithms/fracture/voronoi/cell_clipper.h"
#include "algorithms/fracture/voronoi/voronoi_cells.h"

#include <algorithm>
#include <memory>
#include <numeric>
#include <string>
#include <utility>

namespace shatter {
namespace {

/// State of one fracture: the sites, their cells, and the fragments found so far per site.
class CellCutter {
 public:
  /// `tolerance` (m) is far above the round-off of a crossing point and far below any cell.
  /// Parts of cell i go to `parts[i]`.
  CellCutter(std::span<const Vec3> sites, const std::vector<VoronoiCell>& cells, int leaf_cells, double tolerance,
             std::vector<std::vector<Fragment>>& parts)
      : sites_(sites), cells_(cells), leaf_cells_(leaf_cells), tolerance_(tolerance), parts_(parts) {}

  /// Cuts the cells `ids` out of `piece` (a closed mesh that holds all of them inside the solid).
  void cut(const Mesh& piece, std::span<std::int32_t> ids) {
    if (static_cast<int>(ids.size()) <= leaf_cells_) {
      for (const std::int32_t i : ids) cut_cell(piece, i);
      return;
    }
    const Aabb piece_box = bounding_box(piece);
    Aabb span;
    for (const std::int32_t i : ids) {
      span.extend(cells_[static_cast<std::size_t>(i)].bounds.min.cwiseMax(piece_box.min));
      span.extend(cells_[static_cast<std::size_t>(i)].bounds.max.cwiseMin(piece_box.max));
    }
    int axis = 0;
    const Vec3 extent = span.max - span.min;
    if (extent.y() > extent[axis]) axis = 1;
    if (extent.z() > extent[axis]) axis = 2;
    std::sort(ids.begin(), ids.end(), [&](std::int32_t a, std::int32_t b) {
      const double ka = sites_[static_cast<std::size_t>(a)][axis];
      const double kb = sites_[static_cast<std::size_t>(b)][axis];
      return ka < kb || (ka == kb && a < b);
    });
    const std::size_t half = ids.size() / 2;
    const std::span<std::int32_t> lower = ids.first(half);
    const std::span<std::int32_t> upper = ids.subspan(half);
    double lower_max = -std::numeric_limits<double>::infinity();
    double upper_min = std::numeric_limits<double>::infinity();
    for (const std::int32_t i : lower) lower_max = std::max(lower_max, cells_[static_cast<std::size_t>(i)].bounds.max[axis]);
    for (const std::int32_t i : upper) upper_min = std::min(upper_min, cells_[static_cast<std::size_t>(i)].bounds.min[axis]);
    Vec3 normal = Vec3::Zero();
    normal[axis] = 1.0;
    cut_side(piece, piece_box, axis, lower_max, normal, lower);
    cut_side(piece, piece_box, axis, upper_min, -normal, upper);
  }

 private:
  /// Recurses into the part of `piece` on the negative side of the axis plane at `at` (the side
  /// that holds the cells `ids`), or into `piece` itself when the plane misses it.
  void cut_side(const Mesh& piece, const Aabb& piece_box, int axis, double at, const Vec3& normal,
                std::span<std::int32_t> ids) {
    Plane plane{0.5 * (piece_box.min + piece_box.max), normal};
    plane.point[axis] = at;
    // A plane at (or within round-off of) the piece's extent would re-cut the cap of an earlier cut at
    // the same place, whose rounded points straddle it: skip it, keeping more is always valid.
    const bool misses = normal[axis] > 0 ? at >= piece_box.max[axis] - tolerance_
                                         : at <= piece_box.min[axis] + tolerance_;
    if (misses) return cut(piece, ids);
    Mesh kept;
    Mesh dropped;
    switch (slicer_.slice(piece, plane, kept, dropped)) {
      case SliceOutcome::cut: return cut(kept, ids);
      case SliceOutcome::all_above: return;  // the cells lie beyond the piece: none meets it
      case SliceOutcome::all_below:
      case SliceOutcome::failed: return cut(piece, ids);  // keeping more than needed is still valid
    }
  }

  /// Cuts cell `i` out of `piece` by its bisectors and stores its connected parts. Greedy order: each
  /// step slices by the bisector that a double-precision count says removes the most vertices, and
  /// drops the bisectors that clearly miss the piece (they miss every later, smaller piece too).
  void cut_cell(const Mesh& piece, std::int32_t i) {
    const Vec3& site = sites_[static_cast<std::size_t>(i)];
    const Mesh* current = &piece;
    Mesh owned;
    Mesh below;
    Mesh above;
    const double reach2 = reach_squared(*current, site);
    candidates_.clear();
    for (const std::int32_t j : cells_[static_cast<std::size_t>(i)].neighbours) {
      if ((sites_[static_cast<std::size_t>(j)] - site).squaredNorm() > 4.0 * reach2) break;
      candidates_.push_back(bisector_plane(sites_, i, j));
    }
    // Round-off of a dot product is far below this share of |normal| x reach.
    const double tolerance = 1e-10 * std::sqrt(reach2);
    while (!candidates_.empty()) {
      std::size_t best = 0;
      std::size_t best_count = 0;
      for (std::size_t k = 0; k < candidates_.size();) {
        const Plane& plane = candidates_[k];
        const double slack = tolerance * plane.normal.norm();
        std::size_t removed = 0;
        bool touches = false;
        for (const Vec3& v : current->vertices) {
          const double d = plane.normal.dot(v - plane.point);
          removed += d > 0;
          touches |= d > -slack;
        }
        if (!touches) {  // clearly all on the site's side: never cuts
          candidates_[k] = candidates_.back();
          candidates_.pop_back();
          continue;
        }
        if (removed > best_count || (removed == best_count && k == 0)) {
          best = k;
          best_count = removed;
        }
        ++k;
      }
      if (candidates_.empty()) break;
      const Plane plane = candidates_[best];
      candidates_.erase(candidates_.begin() + static_cast<std::ptrdiff_t>(best));
      switch (slicer_.slice(*current, plane, below, above)) {
        case SliceOutcome::cut:
          std::swap(owned, below);
          current = &owned;
          break;
        case SliceOutcome::all_above: return;  // nothing of the piece is closer to site i
        case SliceOutcome::all_below: break;
        case SliceOutcome::failed:
          if (!slice_by_component(*current, plane, below)) ++failed_cuts_;
          if (below.empty()) return;
          std::swap(owned, below);
          current = &owned;
          break;
      }
    }
    std::vector<Mesh> parts = current == &piece ? volume_components(piece) : volume_components(std::move(owned));
    for (Mesh& part : parts) {
      const MassProperties mass = mass_properties(part);
      parts_[static_cast<std::size_t>(i)].push_back({std::move(part), mass});
    }
  }

  /// Fallback when a slice of `piece` fails, as when shells of the input overlap so that their cut
  /// outlines cross: slices each connected part on its own and gathers the parts below the plane
  /// into `below`. A part that still fails is kept whole (false is returned).
  bool slice_by_component(const Mesh& piece, const Plane& plane, Mesh& below) {
    below = Mesh{};
    copy_attribute_frame(piece, below);
    bool ok = true;
    Mesh part_below;
    Mesh part_above;
    for (const Mesh& part : volume_components(piece)) {
      const Mesh* kept = &part;
      switch (slicer_.slice(part, plane, part_below, part_above)) {
        case SliceOutcome::cut: kept = &part_below; break;
        case SliceOutcome::all_above: kept = nullptr; break;
        case SliceOutcome::all_below: break;
        case SliceOutcome::failed: ok = false; break;
      }
      if (kept != nullptr) append_mesh(below, *kept);
    }
    return ok;
  }

  /// Squared distance from `site` to the farthest vertex of `mesh`, m^2, slightly inflated so that
  /// round-off never skips a bisector that cuts.
  static double reach_squared(const Mesh& mesh, const Vec3& site) {
    double r2 = 0.0;
    for (const Vec3& v : mesh.vertices) r2 = std::max(r2, (v - site).squaredNorm());
    return r2 * (1.0 + 1e-9);
  }

  std::span<const Vec3> sites_;
  const std::vector<VoronoiCell>& cells_;
  int leaf_cells_;
  double tolerance_;
  std::vector<std::vector<Fragment>>& parts_;
  MeshSlicer slicer_;
  std::vector<Plane> candidates_;  // bisectors of the cell being cut that may still cut its piece
  int failed_cuts_ = 0;
};

Status check_sites(std::span<const Vec3> sites) {
  if (sites.empty() || sites.size() > static_cast<std::size_t>(kMaxFragments))
    return Error{"voronoi: needs between 1 and " + std::to_string(kMaxFragments) + " sites, got " +
                 std::to_string(sites.size())};
  std::vector<Vec3> sorted(sites.begin(), sites.end());
  for (std::size_t k = 0; k < sorted.size(); ++k)
    if (!within_coordinate_range(sorted[k]))
      return Error{"voronoi: site " + std::to_string(k) + " is not within +-1e9 m (the representable range)"};
  std::sort(sorted.begin(), sorted.end(), [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    return Error{"voronoi: two sites coincide (their bisector is undefined)"};
  return {};
}

Status check_settings(const VoronoiSettings& s) {
  if (!(s.sites.impact_share >= 0.0 && s.sites.impact_share <= 1.0))
    return Error{"voronoi: impact_share must be in [0, 1], got " + std::to_string(s.sites.impact_share)};
  if (s.sites.max_draws_per_site < 1)
    return Error{"voronoi: max_draws_per_site must be >= 1, got " + std::to_string(s.sites.max_draws_per_site)};
  if (s.leaf_cells < 1) return Error{"voronoi: leaf_cells must be >= 1, got " + std::to_string(s.leaf_cells)};
  return {};
}

/// `fragments`, or the error of a corner value that overflowed (fracture_attributes_bounded says when
/// none can, and then the output is not read).
Result<std::vector<Fragment>> with_finite_corners(std::vector<Fragment>&& fragments, const Mesh& solid) {
  if (!has_attributes(solid) || fracture_attributes_bounded(solid)) return std::move(fragments);
  for (const Fragment& f : fragments)
    if (!all_finite(f.mesh.attributes.corners.data(), f.mesh.attributes.corners.size()))
      return Error{std::string("voronoi: ") + kAttributeOverflow};
  return std::move(fragments);
}

}  // namespace

Result<std::vector<Fragment>> VoronoiFracturer::fracture(const Mesh& solid, const FractureParams& params) const {
  if (Status s = check_fracture_params(solid, params, "voronoi"); !s) return s.error();
  if (Status s = check_settings(settings_); !s) return s.error();
  const PointInMesh inside(solid);
  Result<std::vector<Vec3>> sites = sample_sites(inside, params, settings_.sites);
  if (!sites) return sites.error();
  if (Status s = check_sites(*sites); !s) return s.error();
  return with_finite_corners(cut_cells(solid, *sites, &inside), solid);
}

Result<std::vector<Fragment>> VoronoiFracturer::fracture_with_sites(const Mesh& solid,
                                                                    std::span<const Vec3> sites) const {
  if (Status s = check_fracture_solid(solid, "voronoi", nullptr); !s) return s.error();
  if (Status s = check_sites(sites); !s) return s.error();
  if (Status s = check_settings(settings_); !s) return s.error();
  return with_finite_corners(cut_cells(solid, sites, nullptr), solid);
}

std::vector<Fragment> VoronoiFracturer::cut_cells(const Mesh& solid, std::span<const Vec3> sites,
                                                  const PointInMesh* inside) const {
  Aabb box = bounding_box(solid);
  const double margin = 1e-9 * std::max(box.diagonal(), 1e-300) + 1e-300;
  box.min.array() -= 4 * margin;
  box.max.array() += 4 * margin;
  for (const Vec3& s : sites) box.extend(s);  // every site inside the box its cell is clipped to
  const std::vector<VoronoiCell> cells = voronoi_cells(sites, box, 64 * margin);
  std::vector<std::vector<Fragment>> parts(sites.size());
  // Each cell in one pass over the triangles near it; the few the clipper cannot decide are cut by
  // the sequential slicer, from a site tree over just those cells.
  std::vector<std::int32_t> sequential;
  CellClipper clipper(solid, sites, inside);
  std::vector<Plane> planes;
  Mesh cell;
  for (int i = 0; i < static_cast<int>(sites.size()); ++i) {
    const VoronoiCell& c = cells[static_cast<std::size_t>(i)];
    planes.clear();
    for (const std::int32_t j : c.neighbours) planes.push_back(bisector_plane(sites, i, j));
    if (!clipper.clip(i, planes, c.polytope, box, c.bounds, cell)) {
      sequential.push_back(i);
      continue;
    }
    if (cell.empty()) continue;
    for (Mesh& part : volume_components(std::move(cell))) {
      const MassProperties mass = mass_properties(part);
      parts[static_cast<std::size_t>(i)].push_back({std::move(part), mass});
    }
    cell = Mesh{};
  }
  if (!sequential.empty()) {
    CellCutter cutter(sites, cells, settings_.leaf_cells, margin, parts);
    cutter.cut(solid, sequential);
  }
  std::vector<Fragment> out;
  for (auto& cell_parts : parts)
    for (Fragment& f : cell_parts) out.push_back(std::move(f));
  return out;
}

Result<std::optional<CutPlan>> VoronoiFracturer::cut_plan(const Mesh& solid, const FractureParams& params) const {
  if (Status s = check_fracture_params(solid, params, "voronoi"); !s) return s.error();
  if (Status s = check_settings(settings_); !s) return s.error();
  Result<std::vector<Vec3>> sites = sample_sites(solid, params, settings_.sites);
  if (!sites) return sites.error();
  const int n = static_cast<int>(sites->size());
  CellCuts plan;
  plan.cells.resize(sites->size());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (i != j) plan.cells[static_cast<std::size_t>(i)].planes.push_back(bisector_plane(*sites, i, j));
  return std::optional<CutPlan>(std::move(plan));
}

std::vector<SettingDoc> voronoi_setting_docs() {
  return {{"impact_share", "", "0.5", "[0, 1]", "share of the sites clustered in the impact's ball", {}},
          {"max_draws_per_site", "draws", "2000", "[1, 1000000]", "random draws per site before giving up", {}},
          {"leaf_cells", "cells", "1", "[1, 100000]", "cells cut straight from their node's piece", {}}};
}

Result<VoronoiSettings> read_voronoi_settings(const PluginSettings& settings) {
  const std::vector<SettingDoc> docs = voronoi_setting_docs();
  const SettingsReader r("voronoi", settings, docs);
  VoronoiSettings v;
  if (Status s = r.check_keys(); !s) return s.error();
  if (Status s = r.number("impact_share", 0.0, 1.0, v.sites.impact_share); !s) return s.error();
  if (Status s = r.integer("max_draws_per_site", 1, 1000000, v.sites.max_draws_per_site); !s) return s.error();
  if (Status s = r.integer("leaf_cells", 1, 100000, v.leaf_cells); !s) return s.error();
  return v;
}

void register_voronoi(FracturerRegistry& registry) {
  registry.add("voronoi", "Voronoi cells of uniform or impact-clustered sites, cut by bisector planes",
               voronoi_setting_docs(), [](const PluginSettings& settings) -> Result<std::unique_ptr<Fracturer>> {
                 Result<VoronoiSettings> v = read_voronoi_settings(settings);
                 if (!v) return v.error();
                 return std::unique_ptr<Fracturer>(std::make_unique<VoronoiFracturer>(*v));
               });
}

}  // namespace shatter
