// Design note: voro++ gives each site's cell and, for every face, the neighbouring site across it.
// The cut uses the exact bisector of the two sites, not voro++'s floating-point face: both cells of a
// face then cut with the same plane (its point is (a + b) / 2 in both, the normal negated), the
// slicer's side tests are exact, and the cells partition the solid. Faces on voro++'s container walls
// are left out: the container holds the whole solid.

#include "voro_fracturer.h"

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh.h"
#include "algorithms/core/volume_components.h"
#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/fracture/plane_slice/mesh_slicer.h"
#include "algorithms/fracture/voronoi/voronoi_sites.h"

#include <voro++/voro++.hh>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace voro_plugin {
namespace {

using shatter::Vec3;

/// The bisector of sites a and b, below it a's side.
shatter::Plane bisector(const Vec3& a, const Vec3& b) {
  shatter::Plane plane;
  plane.point = (a + b) * 0.5;
  plane.normal = b - a;
  return plane;
}

/// Each site's cell as the bisectors with its voro++ neighbours.
std::vector<shatter::ConvexCell> voro_cells(const std::vector<Vec3>& sites, const shatter::Aabb& solid_box) {
  const Vec3 size = solid_box.max - solid_box.min;
  const double pad = 0.01 * std::max(size.norm(), 1e-9);
  Vec3 lo = solid_box.min - Vec3::Constant(pad);
  Vec3 hi = solid_box.max + Vec3::Constant(pad);
  for (const Vec3& s : sites) {
    lo = lo.cwiseMin(s - Vec3::Constant(pad));
    hi = hi.cwiseMax(s + Vec3::Constant(pad));
  }
  // About five sites per block of voro++'s grid.
  const int blocks = std::max(1, static_cast<int>(std::cbrt(static_cast<double>(sites.size()) / 5.0)));
  voro::container container(lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z(), blocks, blocks, blocks, false, false,
                            false, 8);
  for (std::size_t i = 0; i < sites.size(); ++i)
    container.put(static_cast<int>(i), sites[i].x(), sites[i].y(), sites[i].z());
  std::vector<shatter::ConvexCell> cells(sites.size());
  voro::c_loop_all loop(container);
  voro::voronoicell_neighbor cell;
  std::vector<int> neighbours;
  if (loop.start()) {
    do {
      if (!container.compute_cell(cell, loop)) continue;
      const int i = loop.pid();
      cell.neighbors(neighbours);
      for (const int j : neighbours)
        if (j >= 0) cells[static_cast<std::size_t>(i)].planes.push_back(bisector(sites[static_cast<std::size_t>(i)],
                                                                                  sites[static_cast<std::size_t>(j)]));
    } while (loop.inc());
  }
  return cells;
}

class VoroFracturer final : public shatter::Fracturer {
 public:
  [[nodiscard]] std::string_view name() const override { return "voro++"; }

  [[nodiscard]] shatter::Result<std::vector<shatter::Fragment>> fracture(
      const shatter::Mesh& solid, const shatter::FractureParams& params) const override {
    shatter::Result<std::vector<shatter::ConvexCell>> cells = plan(solid, params);
    if (!cells) return cells.error();
    std::vector<shatter::Fragment> out;
    shatter::MeshSlicer slicer;
    for (const shatter::ConvexCell& cell : *cells) {
      shatter::Mesh piece = solid;
      bool empty = false;
      for (const shatter::Plane& plane : cell.planes) {
        shatter::Mesh below;
        shatter::Mesh above;
        const shatter::SliceOutcome outcome = slicer.slice(piece, plane, below, above);
        if (outcome == shatter::SliceOutcome::failed) return shatter::Error{"voro++: " + slicer.error()};
        if (outcome == shatter::SliceOutcome::all_above) {
          empty = true;
          break;
        }
        if (outcome == shatter::SliceOutcome::cut) piece = std::move(below);
      }
      if (empty) continue;
      for (shatter::Mesh& part : shatter::volume_components(std::move(piece))) {
        const shatter::MassProperties mass = shatter::mass_properties(part);
        out.push_back({std::move(part), mass});
      }
    }
    return out;
  }

  /// The cells, for the exact replay of `accuracy` (cgal-clip cuts the same half-spaces exactly).
  [[nodiscard]] shatter::Result<std::optional<shatter::CutPlan>> cut_plan(
      const shatter::Mesh& solid, const shatter::FractureParams& params) const override {
    shatter::Result<std::vector<shatter::ConvexCell>> cells = plan(solid, params);
    if (!cells) return cells.error();
    return std::optional<shatter::CutPlan>(shatter::CellCuts{std::move(*cells)});
  }

 private:
  static shatter::Result<std::vector<shatter::ConvexCell>> plan(const shatter::Mesh& solid,
                                                                const shatter::FractureParams& params) {
    if (shatter::Status s = shatter::check_fracture_params(solid, params, "voro++"); !s) return s.error();
    // Sites uniform inside the solid (or around the impact), as the built-in voronoi places them.
    shatter::Result<std::vector<Vec3>> sites = shatter::sample_sites(solid, params);
    if (!sites) return sites.error();
    return voro_cells(*sites, shatter::bounding_box(solid));
  }
};

}  // namespace

void register_voro(shatter::Registries& registries) {
  registries.fracturers.add(
      "voro++", "Voronoi cells computed by voro++, cut by the exact slicing kernel (example plugin)", {},
      [](const shatter::PluginSettings&) -> shatter::Result<std::unique_ptr<shatter::Fracturer>> {
        return std::unique_ptr<shatter::Fracturer>(std::make_unique<VoroFracturer>());
      });
}

}  // namespace voro_plugin
