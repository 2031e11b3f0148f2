#include "harness/pipeline/case_structure.h"

#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "algorithms/registry/register_all.h"
#include "harness/cases/case_mesh.h"

#include <string>

namespace shatter {
namespace {

bool overlaps(const Aabb& a, const Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

}  // namespace

Result<std::vector<Fragment>> prefracture_case(const Case& c, const Solid& solid) {
  if (c.prefracture.explicit_planes()) {
    auto fragments = PlaneSliceFracturer().fracture_by_planes(solid.mesh, c.prefracture.planes);
    if (!fragments) return Error{c.name + ": prefracture.planes: " + fragments.error().message};
    return fragments;
  }
  auto fracturer = registries().fracturers.create(c.prefracture.fracturer);
  if (!fracturer) return Error{c.name + ": prefracture.fracturer: " + fracturer.error().message};
  FractureParams params;
  params.fragments = c.prefracture.fragments;
  params.seed = c.prefracture.seed;
  auto fragments = (*fracturer)->fracture(solid.mesh, params);
  if (!fragments) return Error{c.name + ": prefracture: " + fragments.error().message};
  return fragments;
}

Result<CaseStructure> build_case_structure(const Case& c) {
  Result<Solid> solid = build_case_solid(c);
  if (!solid) return solid.error();
  Result<std::vector<Fragment>> fragments = prefracture_case(c, *solid);
  if (!fragments) return fragments.error();

  std::vector<Aabb> anchors;
  for (std::size_t i = 0; i < c.anchors.size(); ++i) {
    const Aabb& region = c.anchors[i];
    bool touches = false;
    for (const Fragment& f : *fragments) touches = touches || overlaps(bounding_box(f.mesh), region);
    if (!touches) return Error{c.name + ": anchors[" + std::to_string(i) + "]: the region touches no fragment"};
    anchors.push_back(region);
  }
  SupportGraphSettings settings;
  settings.density = c.material.density;
  Result<SupportGraph> graph = build_support_graph(*fragments, anchors, settings);
  if (!graph) return Error{c.name + ": " + graph.error().message};

  CaseStructure out;
  out.solid = std::move(*solid);
  out.fragments = std::move(*fragments);
  out.graph = std::move(*graph);
  return out;
}

}  // namespace shatter
