// "slabs": the smallest fracturer worth loading, as a whole plugin in one file. It cuts the solid into
// `fragments` slabs of equal thickness across one axis of its bounding box (the longest, unless the
// setting `axis` names one) with shatterbench's own slicing kernel (PlaneSliceFracturer::
// fracture_by_planes, which resolves against the shatterbench executable that loads the plugin), and
// states those planes as its cut plan, so `accuracy --family fracture` replays them exactly.
//
// The seed and the impact are ignored: the slabs depend on the solid, the count and the axis only, so
// every seed gives the same fragments. A slab of a non-convex solid may fall apart into several pieces,
// each its own fragment, so `fragments` is a lower bound there.

#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "algorithms/registry/plugin_api.h"

#include <memory>
#include <optional>
#include <vector>

namespace {

using shatter::FractureParams;
using shatter::Mesh;
using shatter::Plane;
using shatter::Result;
using shatter::Vec3;

/// The fragments - 1 planes between equal slabs of `solid` across `axis` (0, 1, 2 for x, y, z; -1 for
/// the longest side of its box), in order along the axis; unit normals.
std::vector<Plane> slab_planes(const Mesh& solid, int fragments, int axis) {
  const shatter::Aabb box = shatter::bounding_box(solid);
  const Vec3 size = box.max - box.min;
  if (axis < 0) {
    Eigen::Index longest = 0;
    size.maxCoeff(&longest);
    axis = static_cast<int>(longest);
  }
  std::vector<Plane> planes;
  for (int k = 1; k < fragments; ++k) {
    Plane plane;
    plane.point = (box.min + box.max) * 0.5;
    plane.point[axis] = box.min[axis] + size[axis] * k / fragments;
    plane.normal = Vec3::Unit(axis);
    planes.push_back(plane);
  }
  return planes;
}

class SlabsFracturer final : public shatter::Fracturer {
 public:
  /// Slabs across `axis` (as slab_planes takes it).
  explicit SlabsFracturer(int axis) : axis_(axis) {}

  [[nodiscard]] std::string_view name() const override { return "slabs"; }

  [[nodiscard]] Result<std::vector<shatter::Fragment>> fracture(const Mesh& solid,
                                                                const FractureParams& params) const override {
    // The request here; fracture_by_planes checks the solid and the planes.
    if (shatter::Status s = shatter::check_fracture_request(params, "slabs"); !s) return s.error();
    const std::vector<Plane> planes = slab_planes(solid, params.fragments, axis_);
    return shatter::PlaneSliceFracturer().fracture_by_planes(solid, planes, shatter::kMaxFragments, params.verdicts);
  }

  /// The same planes, for the exact replay (every piece a plane crosses is split, as fracture_by_planes does).
  [[nodiscard]] Result<std::optional<shatter::CutPlan>> cut_plan(const Mesh& solid,
                                                                 const FractureParams& params) const override {
    if (shatter::Status s = shatter::check_fracture_params(solid, params, "slabs"); !s) return s.error();
    return std::optional<shatter::CutPlan>(shatter::PlaneCuts{slab_planes(solid, params.fragments, axis_)});
  }

 private:
  int axis_;
};

/// Adds "slabs" and its one setting.
void register_slabs(shatter::Registries& registries) {
  std::vector<shatter::SettingDoc> docs = {
      {"axis", "", "-1", "[-1, 2]",
       "axis the slabs are cut across: 0, 1, 2 for x, y, z; -1 the longest side of the box", {}}};
  registries.fracturers.add(
      "slabs", "equal slabs across the longest side of the solid's box, plane-slice's kernel (example plugin)", docs,
      [docs](const shatter::PluginSettings& settings) -> Result<std::unique_ptr<shatter::Fracturer>> {
        const shatter::SettingsReader reader("slabs", settings, docs);
        int axis = -1;
        if (shatter::Status s = reader.check_keys(); !s) return s.error();
        if (shatter::Status s = reader.integer("axis", -1, 2, axis); !s) return s.error();
        return std::unique_ptr<shatter::Fracturer>(std::make_unique<SlabsFracturer>(axis));
      });
}

}  // namespace

SHATTERBENCH_PLUGIN(register_slabs)
