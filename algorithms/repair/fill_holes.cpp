// triangulate_refine_and_fair_hole solves its fairing system with Eigen (a dependency of the tree).
#ifndef CGAL_EIGEN3_ENABLED
#define CGAL_EIGEN3_ENABLED
#endif
#include "algorithms/repair/fill_holes.h"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace shatter::repair {
namespace {

using Halfedge = SurfaceMesh::Halfedge_index;

/// Longest border cycle whose triangulation is searched exhaustively when the Delaunay-restricted
/// search fails (the search costs the cube of the length: 300 edges take about a second).
constexpr std::size_t max_exhaustive_cycle = 300;

/// Per part: signed volume (about the part's first corner, against cancellation), filling area.
struct PartMeasure {
  bool has_origin = false;
  Point origin;
  double six_volume = 0.0;
  double fill_area = 0.0;
};

}  // namespace

HoleFilling fill_holes(SurfaceMesh& surface, double min_depth_ratio, bool refine_and_fair) {
  HoleFilling report;
  std::vector<Halfedge> cycles;
  PMP::extract_boundary_cycles(surface, std::back_inserter(cycles));
  if (cycles.empty()) return report;

  auto is_fill = surface.add_property_map<FaceIndex, bool>("f:repair_fill", false).first;
  std::vector<FaceIndex> filled;    // one new face per filled cycle
  std::vector<FaceIndex> unfilled;  // one face beside each cycle that could not be filled
  for (Halfedge h : cycles) {
    if (!surface.is_border(h)) continue;  // closed by an earlier filling
    std::vector<FaceIndex> added;
    if (refine_and_fair) {
      std::vector<SurfaceMesh::Vertex_index> new_vertices;
      PMP::triangulate_refine_and_fair_hole(surface, h, std::back_inserter(added), std::back_inserter(new_vertices),
                                            PMP::parameters::use_2d_constrained_delaunay_triangulation(true));
    } else {
      PMP::triangulate_hole(surface, h, std::back_inserter(added),
                            PMP::parameters::use_2d_constrained_delaunay_triangulation(true));
    }
    if (added.empty() && surface.is_border(h) && CGAL::halfedges_around_face(h, surface).size() <= max_exhaustive_cycle) {
      // The Delaunay-restricted search found no triangulation: search all of them (cubic in the length).
      PMP::triangulate_hole(surface, h, std::back_inserter(added), PMP::parameters::use_delaunay_triangulation(false));
    }
    if (added.empty()) {
      ++report.holes_unfilled;
      unfilled.push_back(surface.face(surface.opposite(h)));
      continue;
    }
    filled.push_back(added.front());
    for (FaceIndex f : added) is_fill[f] = true;
  }

  auto part = surface.add_property_map<FaceIndex, std::size_t>("f:repair_part", 0).first;
  const std::size_t parts = PMP::connected_components(surface, part);
  std::vector<PartMeasure> measure(parts);
  for (FaceIndex f : surface.faces()) {
    PartMeasure& m = measure[part[f]];
    const auto h = surface.halfedge(f);
    const Point& a = surface.point(surface.source(h));
    const Point& b = surface.point(surface.target(h));
    const Point& c = surface.point(surface.target(surface.next(h)));
    if (!m.has_origin) {
      m.origin = a;
      m.has_origin = true;
    }
    const auto u = a - m.origin, v = b - m.origin, w = c - m.origin;
    m.six_volume += CGAL::scalar_product(u, CGAL::cross_product(v, w));
    if (is_fill[f]) m.fill_area += std::sqrt(CGAL::squared_area(a, b, c));
  }
  std::vector<std::size_t> sheets;
  std::vector<bool> is_sheet(parts, false);
  std::vector<bool> open(parts, false);
  for (FaceIndex f : unfilled) open[part[f]] = true;
  for (std::size_t p = 0; p < parts; ++p) {
    const PartMeasure& m = measure[p];
    if (open[p]) {  // a border no triangulation closes (a flat sheet whose corners all lie on it)
      sheets.push_back(p);
      is_sheet[p] = true;
      ++report.sheets_removed;
      continue;
    }
    if (m.fill_area <= 0.0) continue;
    const double depth_ratio = std::abs(m.six_volume) / 6.0 / std::pow(m.fill_area, 1.5);
    if (depth_ratio < min_depth_ratio) {
      sheets.push_back(p);
      is_sheet[p] = true;
      ++report.sheets_removed;
    } else {
      report.hole_area += m.fill_area;
    }
  }
  for (FaceIndex f : filled)
    if (!is_sheet[part[f]]) ++report.holes_filled;
  if (!sheets.empty()) PMP::remove_connected_components(surface, sheets, part);
  surface.remove_property_map(part);
  surface.remove_property_map(is_fill);
  return report;
}

}  // namespace shatter::repair
