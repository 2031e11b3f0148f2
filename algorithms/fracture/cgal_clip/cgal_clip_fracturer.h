#pragma once
/// cgal-clip: the exact reference. The same cut schedule as plane-slice (recursive_slicing.h), each
/// cut done by CGAL's Polygon_mesh_processing on an exact-constructions kernel. CGAL stays inside
/// this folder's translation units.

#include "algorithms/core/plane.h"
#include "algorithms/fracture/fracturer.h"
#include "algorithms/fracture/fracturer_registry.h"

#include <span>

namespace shatter {

/// The cgal-clip reference fracturer.
class CgalClipFracturer final : public Fracturer {
 public:
  [[nodiscard]] std::string_view name() const override { return "cgal-clip"; }
  [[nodiscard]] Result<std::vector<Fragment>> fracture(const Mesh& solid,
                                                       const FractureParams& params) const override;
  /// Cuts `solid` by each plane in turn, as PlaneSliceFracturer::fracture_by_planes.
  [[nodiscard]] Result<std::vector<Fragment>> fracture_by_planes(const Mesh& solid,
                                                                 std::span<const Plane> planes) const;
};

/// Registers "cgal-clip".
void register_cgal_clip(FracturerRegistry& registry);

}  // namespace shatter
