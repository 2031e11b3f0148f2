#include "algorithms/repair/orient_volumes.h"

#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <cstddef>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace shatter::repair {

VolumeShells orient_volumes(SurfaceMesh& surface) {
  VolumeShells result;
  if (surface.number_of_faces() == 0 || !CGAL::is_closed(surface)) return result;
  result.closed = true;
  PMP::orient_to_bound_a_volume(surface);
  auto volume = surface.add_property_map<FaceIndex, std::size_t>("f:repair_volume", 0).first;
  std::vector<std::size_t> nesting;
  PMP::volume_connected_components(surface, volume,
                                   PMP::parameters::nesting_levels(std::ref(nesting)).do_self_intersection_tests(false));
  surface.remove_property_map(volume);
  result.shells = static_cast<int>(nesting.size());
  for (std::size_t level : nesting)
    if (level % 2 == 1) ++result.cavities;
  return result;
}

}  // namespace shatter::repair
