#pragma once
/// A fracturer's capability to cut where the caller says: by explicit planes, in order. Asked for
/// through Fracturer::plane_cutting(); the harness cuts a case's explicit planes and the stability
/// battery's exact planes with a fracturer that offers it, chosen by the capability, never by name.

#include "algorithms/core/fragment.h"
#include "algorithms/core/mesh.h"
#include "algorithms/core/plane.h"
#include "algorithms/core/result.h"

#include <span>
#include <vector>

namespace shatter {

/// Cutting a solid by planes the caller chooses.
class PlaneCutting {
 public:
  virtual ~PlaneCutting() = default;
  /// Cuts `solid` (a validated closed mesh) by each of `planes` in turn (m, unit normals), every piece
  /// a plane crosses split in two and a piece a plane misses left whole; the pieces as closed
  /// fragments. Errors for planes or a solid it cannot cut, as Fracturer::fracture does.
  [[nodiscard]] virtual Result<std::vector<Fragment>> cut_by_planes(const Mesh& solid,
                                                                    std::span<const Plane> planes) const = 0;
};

}  // namespace shatter
