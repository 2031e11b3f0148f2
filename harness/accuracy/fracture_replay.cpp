#include "harness/accuracy/fracture_replay.h"

#include "algorithms/fracture/cgal_clip/cgal_clip_fracturer.h"
#include "algorithms/fracture/fem_lite/fem_lite_fracturer.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "algorithms/fracture/voronoi/voronoi_cells.h"
#include "algorithms/fracture/voronoi/voronoi_fracturer.h"
#include "algorithms/fracture/voronoi/voronoi_sites.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace shatter {

Result<std::vector<Fragment>> exact_replay(const Fracturer& fracturer, const Mesh& solid, const FractureParams& params) {
  const CgalClipFracturer exact;
  if (dynamic_cast<const PlaneSliceFracturer*>(&fracturer)) return exact.fracture(solid, params);
  if (dynamic_cast<const VoronoiFracturer*>(&fracturer)) {
    // The registered voronoi uses the default site settings, as here.
    Result<std::vector<Vec3>> sites = sample_sites(solid, params);
    if (!sites) return sites.error();
    const int n = static_cast<int>(sites->size());
    std::vector<ConvexCell> cells(sites->size());
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (i != j) cells[static_cast<std::size_t>(i)].planes.push_back(bisector_plane(*sites, i, j));
    return exact.fracture_by_cells(solid, cells);
  }
  if (const auto* fem = dynamic_cast<const FemLiteFracturer*>(&fracturer)) {
    Result<std::vector<Plane>> planes = fem->crack_planes(solid, params);
    if (!planes) return planes.error();
    return exact.fracture_by_planes(solid, *planes);
  }
  return Error{"no exact replay for fracturer '" + std::string(fracturer.name()) + "'"};
}

ReplayMismatch replay_mismatch(const std::vector<Fragment>& fast, const std::vector<Fragment>& exact) {
  ReplayMismatch m;
  m.fast_count = static_cast<int>(fast.size());
  m.exact_count = static_cast<int>(exact.size());
  double exact_total = 0.0;
  for (const Fragment& e : exact) exact_total += e.mass.volume;
  std::vector<bool> used(exact.size(), false);
  double unpaired = 0.0;
  for (const Fragment& f : fast) {
    std::size_t best = exact.size();
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < exact.size(); ++k) {
      const double d = (f.mass.centroid - exact[k].mass.centroid).norm();
      if (!used[k] && d < best_distance) {
        best_distance = d;
        best = k;
      }
    }
    if (best == exact.size()) {
      unpaired += std::abs(f.mass.volume);
      continue;
    }
    used[best] = true;
    const double v = exact[best].mass.volume;
    const double relative = v > 0.0 ? std::abs(f.mass.volume - v) / v : std::numeric_limits<double>::infinity();
    m.max_relative_volume = std::max(m.max_relative_volume, relative);
  }
  for (std::size_t k = 0; k < exact.size(); ++k)
    if (!used[k]) unpaired += exact[k].mass.volume;
  m.unpaired_volume = exact_total > 0.0 ? unpaired / exact_total : 0.0;
  return m;
}

}  // namespace shatter
