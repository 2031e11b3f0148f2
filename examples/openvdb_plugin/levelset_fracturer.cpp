// "openvdb-levelset": OpenVDB's level-set fracture (tools::LevelSetFracture), the method behind
// Houdini's VDB fracture, as a shatterbench fracturer. The solid becomes a narrow-band signed distance
// grid (tools::meshToLevelSet) with `resolution` voxels along the longest side of its box; a sphere
// level set, the cutter, is instanced at fragments - 1 sites drawn inside the solid by shatterbench's
// own sample_sites (so the impact shapes them as it shapes the built-ins'); each instance carves its
// fragment out of what is left (no overlap between instances), the remainder is the last fragment,
// and pieces that fall apart are split (segment). Every piece is meshed back at the zero level set
// (tools::volumeToMesh, quads split into triangles) in double.
//
// An approximate method: its surfaces lie within about a voxel of the input's, so the fragments'
// volumes sum to the input's only to a relative error of a few voxels over the size (measured by
// `table` as the volume error). It states that tolerance (Fracturer::volume_tolerance) so that the
// host's output check measures it against it rather than against round-off. A face is tagged `cut`
// where it lies inside the input (its centre deeper than half a voxel in the input's level set),
// `surface` elsewhere. No cut plan: the cuts are spheres on a grid, not planes, so `accuracy` has no
// exact replay of it.

#include "algorithms/core/mass_properties.h"
#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/fracture/voronoi/voronoi_sites.h"
#include "algorithms/registry/plugin_api.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetFracture.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <cmath>
#include <list>
#include <memory>
#include <string>
#include <vector>

namespace {

using shatter::FractureParams;
using shatter::Mesh;
using shatter::Result;
using shatter::Vec3;
using GridPtr = openvdb::FloatGrid::Ptr;

constexpr float kHalfWidth = 3.0f;  // narrow band, voxels

/// The zero level set of `grid` as a closed, outward triangle mesh (double), faces tagged by depth in
/// `input` (the solid's own level set).
Mesh mesh_of(const openvdb::FloatGrid& grid, const openvdb::FloatGrid& input, double voxel) {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(grid, points, triangles, quads, 0.0, 0.0);
  Mesh mesh;
  for (const openvdb::Vec3s& p : points) mesh.add_vertex(Vec3(p.x(), p.y(), p.z()));
  const auto sampler = input.getConstAccessor();
  const openvdb::math::Transform& xform = input.transform();
  const auto tag_of = [&](std::int32_t a, std::int32_t b, std::int32_t c) {
    const Vec3 centre = (mesh.vertices[a] + mesh.vertices[b] + mesh.vertices[c]) / 3.0;
    const openvdb::Coord ijk = xform.worldToIndexCellCentered(openvdb::Vec3d(centre.x(), centre.y(), centre.z()));
    return sampler.getValue(ijk) < -0.5 * voxel ? shatter::FaceTag::cut : shatter::FaceTag::surface;
  };
  // volumeToMesh winds its polygons clockwise seen from outside: reversed here to face outward.
  const auto add = [&](std::int32_t a, std::int32_t b, std::int32_t c) { mesh.add_triangle(a, c, b, tag_of(a, c, b)); };
  for (const openvdb::Vec3I& t : triangles)
    add(static_cast<std::int32_t>(t[0]), static_cast<std::int32_t>(t[1]), static_cast<std::int32_t>(t[2]));
  for (const openvdb::Vec4I& q : quads) {
    add(static_cast<std::int32_t>(q[0]), static_cast<std::int32_t>(q[1]), static_cast<std::int32_t>(q[2]));
    add(static_cast<std::int32_t>(q[0]), static_cast<std::int32_t>(q[2]), static_cast<std::int32_t>(q[3]));
  }
  return mesh;
}

class LevelSetFracturer final : public shatter::Fracturer {
 public:
  LevelSetFracturer(int resolution, double tolerance) : resolution_(resolution), tolerance_(tolerance) {}

  [[nodiscard]] std::string_view name() const override { return "openvdb-levelset"; }
  [[nodiscard]] double volume_tolerance() const override { return tolerance_; }

  [[nodiscard]] Result<std::vector<shatter::Fragment>> fracture(const Mesh& solid,
                                                                const FractureParams& params) const override {
    if (shatter::Status s = shatter::check_fracture_params(solid, params, "openvdb-levelset"); !s) return s.error();
    const shatter::Aabb box = shatter::bounding_box(solid);
    const double voxel = (box.max - box.min).maxCoeff() / resolution_;
    const openvdb::math::Transform::Ptr xform = openvdb::math::Transform::createLinearTransform(voxel);
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    for (const Vec3& v : solid.vertices) points.emplace_back(float(v.x()), float(v.y()), float(v.z()));
    for (const shatter::Triangle& t : solid.triangles)
      triangles.emplace_back(openvdb::Index32(t[0]), openvdb::Index32(t[1]), openvdb::Index32(t[2]));
    const GridPtr input = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*xform, points, triangles, kHalfWidth);

    Result<std::vector<Vec3>> sites = shatter::sample_sites(solid, params);
    if (!sites) return sites.error();
    std::vector<openvdb::Vec3s> offsets;
    for (std::size_t k = 1; k < sites->size(); ++k)
      offsets.emplace_back(float((*sites)[k].x()), float((*sites)[k].y()), float((*sites)[k].z()));
    // Cutter spheres about as large as the fragments asked for: a ball of the solid's volume / count.
    const double volume = shatter::signed_volume(solid);
    const double radius = std::max(std::cbrt(3.0 * volume / (4.0 * M_PI * params.fragments)), 2.0 * voxel);
    const GridPtr cutter = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
        float(radius), openvdb::Vec3f(0.0f), float(voxel), kHalfWidth);

    std::list<GridPtr> grids = {input->deepCopy()};
    openvdb::tools::LevelSetFracture<openvdb::FloatGrid> fracture;
    if (!offsets.empty()) fracture.fracture(grids, *cutter, true, &offsets, nullptr, false);
    grids.splice(grids.end(), fracture.fragments());

    std::vector<shatter::Fragment> out;
    for (const GridPtr& grid : grids) {
      Mesh mesh = mesh_of(*grid, *input, voxel);
      if (mesh.triangles.empty()) continue;
      if (out.size() >= static_cast<std::size_t>(shatter::kMaxFragments))
        return shatter::Error{"openvdb-levelset: more than " + std::to_string(shatter::kMaxFragments) + " fragments"};
      const shatter::MassProperties mass = shatter::mass_properties(mesh);
      out.push_back({std::move(mesh), mass});
    }
    if (out.empty()) return shatter::Error{"openvdb-levelset: the solid is thinner than a voxel at resolution " +
                                           std::to_string(resolution_)};
    return out;
  }

 private:
  int resolution_;
  double tolerance_;
};

void register_levelset(shatter::Registries& registries) {
  openvdb::initialize();
  std::vector<shatter::SettingDoc> docs = {
      {"resolution", "voxels", "128", "[8, 512]", "voxels along the longest side of the solid's box", {32, 64, 128}},
      {"volume_tolerance", "", "0.05", "[0, 0.1]",
       "relative volume error the fragments may carry, stated to the host's output check", {}}};
  registries.fracturers.add(
      "openvdb-levelset", "OpenVDB level-set fracture: sphere cutters at sampled sites on a voxel grid (example plugin)",
      docs, [docs](const shatter::PluginSettings& settings) -> Result<std::unique_ptr<shatter::Fracturer>> {
        const shatter::SettingsReader reader("openvdb-levelset", settings, docs);
        int resolution = 128;
        double tolerance = 0.05;
        if (shatter::Status s = reader.check_keys(); !s) return s.error();
        if (shatter::Status s = reader.integer("resolution", 8, 512, resolution); !s) return s.error();
        if (shatter::Status s = reader.number("volume_tolerance", 0.0, 0.1, tolerance); !s) return s.error();
        return std::unique_ptr<shatter::Fracturer>(std::make_unique<LevelSetFracturer>(resolution, tolerance));
      });
}

}  // namespace

SHATTERBENCH_PLUGIN(register_levelset)
