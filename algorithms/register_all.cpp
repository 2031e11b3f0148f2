#include "algorithms/register_all.h"

#include "algorithms/fracture/cgal_clip/cgal_clip_fracturer.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"

namespace shatter {

void register_all(Registries& registries) {
  register_plane_slice(registries.fracturers);
  register_cgal_clip(registries.fracturers);
}

const Registries& registries() {
  static const Registries instance = [] {
    Registries r;
    register_all(r);
    return r;
  }();
  return instance;
}

}  // namespace shatter
