#include "harness/results/input_solid_json.h"

namespace shatter {

nlohmann::ordered_json repairs_json(const Solid& solid) {
  const RepairReport& r = solid.repair;
  const ValidationReport& v = solid.report;
  // Welding duplicate positions is the one repair that the acceptance rule's own normalisation also
  // does (a UV seam): both count as merged vertices.
  return {{"repaired", r.repaired || v.merged_duplicate_vertices > 0 || v.flipped || v.split_pinched_vertices > 0 ||
                           v.split_non_manifold_edges > 0},
          {"vertices_merged", r.vertices_merged + v.merged_duplicate_vertices},
          {"faces_removed", r.faces_removed},
          {"faces_reoriented", r.faces_reoriented},
          {"vertices_split", v.split_pinched_vertices},
          {"edges_split", v.split_non_manifold_edges},
          {"flipped", v.flipped},
          {"holes_filled", r.holes_filled},
          {"hole_area", r.hole_area},
          {"self_intersections", r.self_intersections},
          {"self_intersection_fix", r.self_intersection_fix},
          {"sheets_removed", r.sheets_removed},
          {"shells", v.shells},
          {"cavities", v.cavities},
          {"hausdorff_distance", r.hausdorff_distance},
          {"time_ms", r.time_ms}};
}

nlohmann::ordered_json input_solid_json(const Solid& solid) {
  return {{"triangles", solid.mesh.triangle_count()},
          {"volume", solid.mass.volume},
          {"area", solid.area},
          {"flipped", solid.report.flipped},
          {"repairs", repairs_json(solid)}};
}

}  // namespace shatter
