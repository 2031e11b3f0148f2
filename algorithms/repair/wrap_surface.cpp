#include "algorithms/repair/wrap_surface.h"

#include <CGAL/alpha_wrap_3.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <cmath>
#include <utility>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace shatter::repair {

bool wrap_surface(SurfaceMesh& surface, double alpha, double offset) {
  if (surface.number_of_faces() == 0) return false;
  const CGAL::Bbox_3 box = PMP::bbox(surface);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  if (!(diagonal > 0.0)) return false;
  SurfaceMesh wrap;
  CGAL::alpha_wrap_3(surface, alpha * diagonal, offset * diagonal, wrap);
  if (wrap.number_of_faces() == 0) return false;
  surface = std::move(wrap);
  origin_map(surface);  // every face new: origin -1
  return true;
}

}  // namespace shatter::repair
