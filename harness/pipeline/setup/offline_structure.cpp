#include "harness/pipeline/setup/offline_structure.h"

#include "algorithms/core/mesh.h"

#include <cassert>
#include <string>
#include <utility>

namespace shatter {
namespace {

bool overlaps(const Aabb& a, const Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

PrefractureKey key_for(const Case& c, const OfflineSetupRequest& request) {
  PrefractureKey key;
  if (c.prefracture.explicit_planes()) {
    key.fracturer = std::string(request.fracturer->name());
    key.planes = c.prefracture.planes;
  } else {
    key.fracturer = std::string(request.fracturer->name());
    if (!request.settings.empty()) key.fracturer += " " + request.settings;
    key.fragments = request.fragments;
    key.seed = request.seed;
  }
  return key;
}

Result<std::vector<Fragment>> fracture_solid(const Case& c, const Solid& solid, const OfflineSetupRequest& request) {
  if (c.prefracture.explicit_planes()) {
    auto fragments = request.fracturer->plane_cutting()->cut_by_planes(solid.mesh, c.prefracture.planes);
    if (!fragments) return Error{c.name + ": prefracture.planes: " + fragments.error().message};
    return fragments;
  }
  FractureParams params;
  params.fragments = request.fragments;
  params.seed = request.seed;
  auto fragments = request.fracturer->fracture(solid.mesh, params);
  if (!fragments) return Error{c.name + ": prefracture: " + fragments.error().message};
  return fragments;
}

/// Per fragment: 1 when it overlaps an anchor region. Every region must touch a fragment.
Result<std::vector<std::uint8_t>> anchored_fragments(const Case& c, const std::vector<Fragment>& fragments) {
  std::vector<std::uint8_t> anchored(fragments.size(), 0);
  for (std::size_t i = 0; i < c.anchors.size(); ++i) {
    bool touches = false;
    for (std::size_t f = 0; f < fragments.size(); ++f) {
      if (overlaps(bounding_box(fragments[f].mesh), c.anchors[i])) {
        anchored[f] = 1;
        touches = true;
      }
    }
    if (!touches) return Error{c.name + ": anchors[" + std::to_string(i) + "]: the region touches no fragment"};
  }
  return anchored;
}

}  // namespace

Result<OfflineStructure> build_offline_structure(const Case& c, const Solid& solid, const OfflineSetupRequest& request,
                                                 StageClocks& setup, StageLog& stages) {
  assert(request.fracturer != nullptr && (!c.prefracture.explicit_planes() || request.fracturer->plane_cutting()));
  OfflineStructure out;
  out.key = key_for(c, request);
  {
    StageTimer timer(setup, Stage::prefracture);
    if (request.cache != nullptr && request.read_cache) {
      if (auto cached = request.cache->load(solid.mesh, out.key)) {
        out.fragments = std::move(*cached);
        out.cache_hit = true;
      }
    }
    if (!out.cache_hit) {
      Result<std::vector<Fragment>> fragments = fracture_solid(c, solid, request);
      if (!fragments) return fragments.error();
      out.fragments = std::move(*fragments);
    }
  }
  if (out.cache_hit) {
    stages.skipped(Stage::prefracture, "unchanged: taken from the cache (" + request.cache->folder().string() + ")");
  } else {
    stages.ran(Stage::prefracture);
    if (request.cache != nullptr) request.cache->store(solid.mesh, out.key, out.fragments);
  }

  Result<std::vector<std::uint8_t>> anchored = anchored_fragments(c, out.fragments);
  if (!anchored) return anchored.error();
  out.anchored = std::move(*anchored);
  if (!request.bonds) {
    stages.skipped(Stage::bonds, "not needed (case needs)");
    return out;
  }
  StageTimer timer(setup, Stage::bonds);
  SupportGraphSettings settings;
  settings.density = c.material.density;
  Result<SupportGraph> graph = build_support_graph(out.fragments, c.anchors, settings);
  if (!graph) return Error{c.name + ": " + graph.error().message};
  out.graph = std::move(*graph);
  stages.ran(Stage::bonds);
  return out;
}

}  // namespace shatter
