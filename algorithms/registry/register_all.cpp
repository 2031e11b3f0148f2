#include "algorithms/registry/registries.h"

#include "algorithms/fracture/cgal_clip/cgal_clip_fracturer.h"
#include "algorithms/fracture/fem_lite/fem_lite_fracturer.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "algorithms/fracture/voronoi/voronoi_fracturer.h"
#include "algorithms/stress/connection_count/connection_count_model.h"
#include "algorithms/stress/rigid_body_spring/local_cascade_model.h"
#include "algorithms/stress/rigid_body_spring/strength_criterion_model.h"

namespace shatter {

void register_all(Registries& registries) {
  register_plane_slice(registries.fracturers);
  register_cgal_clip(registries.fracturers);
  register_voronoi(registries.fracturers);
  register_fem_lite(registries.fracturers);
  register_connection_count(registries.stress_models);
  register_tresca(registries.stress_models);
  register_von_mises(registries.stress_models);
  register_local_cascade_models(registries.stress_models);
}

}  // namespace shatter
