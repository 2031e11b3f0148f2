#include "algorithms/repair/stitch_surface.h"

#include <CGAL/Polygon_mesh_processing/merge_border_vertices.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace shatter::repair {

int stitch_surface(SurfaceMesh& surface) {
  const auto faces_before = static_cast<int>(surface.number_of_faces());
  PMP::stitch_borders(surface);
  PMP::merge_duplicated_vertices_in_boundary_cycles(surface);
  PMP::remove_degenerate_faces(surface);
  return faces_before - static_cast<int>(surface.number_of_faces());
}

}  // namespace shatter::repair
