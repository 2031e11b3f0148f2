#include "algorithms/repair/repair_solid.h"

#include "algorithms/core/mesh_validation.h"
#include "algorithms/repair/autorefine_surface.h"
#include "algorithms/repair/fill_holes.h"
#include "algorithms/repair/hausdorff_distance.h"
#include "algorithms/repair/orient_volumes.h"
#include "algorithms/repair/repair_surface.h"
#include "algorithms/repair/soup_to_surface.h"
#include "algorithms/repair/solid_check.h"
#include "algorithms/repair/stitch_surface.h"
#include "algorithms/repair/wrap_surface.h"

#include <chrono>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace shatter {
namespace {

/// Input triangles whose pieces in `result` face the other way (by the sign of the normals' dot).
int count_reoriented(const Mesh& soup, const Mesh& result, const std::vector<std::int32_t>& origins) {
  auto normal = [](const Mesh& mesh, const Triangle& t) {
    const Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    return Vec3((mesh.vertices[static_cast<std::size_t>(t[1])] - a).cross(mesh.vertices[static_cast<std::size_t>(t[2])] - a));
  };
  std::vector<char> reversed(soup.triangles.size(), 0);
  for (std::size_t f = 0; f < result.triangles.size(); ++f) {
    const std::int32_t from = origins[f];
    if (from < 0) continue;
    const auto i = static_cast<std::size_t>(from);
    if (normal(result, result.triangles[f]).dot(normal(soup, soup.triangles[i])) < 0.0) reversed[i] = 1;
  }
  int count = 0;
  for (char r : reversed) count += r;
  return count;
}

/// The surface as an oriented solid, or why not.
std::optional<std::string> finish(repair::SurfaceMesh& surface, const Mesh& soup, Mesh& result,
                                  std::vector<std::int32_t>& origins, RepairReport& report) {
  const repair::VolumeShells volumes = repair::orient_volumes(surface);
  if (!volumes.closed) return std::string("the surface still has borders");
  report.shells = volumes.shells;
  report.cavities = volumes.cavities;
  result = repair::to_mesh(surface, soup.tags, &origins);
  return repair::solid_defect(result);
}

}  // namespace

Result<RepairedSolid> repair_solid(const Mesh& soup, const std::string& what, const RepairOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  auto fail = [&](const std::string& reason) { return Error{what + ": " + reason}; };
  if (soup.triangles.empty()) return fail("empty mesh (no triangles)");
  if (!all_finite(soup)) return fail("a vertex has a non-finite coordinate");
  const auto vertex_count = static_cast<std::int64_t>(soup.vertices.size());
  for (const Triangle& t : soup.triangles)
    for (const std::int32_t index : t)
      if (index < 0 || index >= vertex_count) return fail("a triangle has a vertex index out of range");

  RepairReport report;
  repair::SoupSurface cleaned = repair::soup_to_surface(soup);
  repair::SurfaceMesh& surface = cleaned.surface;
  report.vertices_merged = cleaned.vertices_merged;
  report.faces_removed = cleaned.faces_removed + repair::stitch_surface(surface);

  const repair::HoleFilling holes = repair::fill_holes(surface, options.min_depth_ratio, options.refine_and_fair_holes);
  report.holes_filled = holes.holes_filled;
  report.hole_area = holes.hole_area;
  report.sheets_removed = holes.sheets_removed;
  if (surface.number_of_faces() == 0)
    return fail(holes.sheets_removed > 0 ? "an open sheet encloses no volume"
                                         : "no triangle with area is left (all degenerate or duplicate)");

  const repair::Autorefinement refined = repair::autorefine_surface(surface);
  report.self_intersections = refined.pairs;
  if (refined.pairs > 0 && refined.resolved) report.self_intersection_fix = "autorefine";

  RepairedSolid solid;
  std::vector<std::int32_t> origins;
  std::optional<std::string> defect =
      refined.resolved ? finish(surface, soup, solid.mesh, origins, report) : std::optional<std::string>(refined.failure);
  if (defect) {
    // One fallback for everything the exact steps leave unsolved: wrap what is there.
    if (!repair::wrap_surface(surface, options.wrap_alpha, options.wrap_offset)) return fail("no solid could be made (" + *defect + ")");
    report.self_intersection_fix = "alpha-wrap";
    if (const auto wrapped = finish(surface, soup, solid.mesh, origins, report))
      return fail("no solid could be made (" + *defect + "; the wrap: " + *wrapped + ")");
  }
  report.faces_reoriented = count_reoriented(soup, solid.mesh, origins);
  report.hausdorff_distance = repair::hausdorff_distance(soup, solid.mesh, options.hausdorff);
  report.repaired = report.vertices_merged > 0 || report.faces_removed > 0 || report.faces_reoriented > 0 ||
                    report.holes_filled > 0 || report.self_intersections > 0 || report.sheets_removed > 0 ||
                    !report.self_intersection_fix.empty();
  report.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  solid.report = std::move(report);
  return solid;
}

}  // namespace shatter
