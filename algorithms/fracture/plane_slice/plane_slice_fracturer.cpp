#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"

#include "algorithms/core/corner_provenance.h"
#include "algorithms/core/mass_properties.h"
#include "algorithms/core/volume_components.h"
#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/fracture/plane_slice/mesh_slicer.h"
#include "algorithms/fracture/recursive_slicing.h"

#include <algorithm>
#include <memory>
#include <optional>

namespace shatter {
namespace {

/// The slicing kernel of recursive_slicing.h over MeshSlicer. An attributed solid is cut as tracked
/// pieces (corner_provenance.h): the corner values are evaluated once, on the fragments.
class SliceKernel {
 public:
  explicit SliceKernel(CornerProvenance* provenance) : provenance_(provenance) {}

  struct Piece {
    Mesh mesh;
    MassProperties mass;
  };

  [[nodiscard]] Vec3 centroid(const Piece& piece) const { return piece.mass.centroid; }

  void split(const Piece& piece, const Plane& plane, std::vector<Piece>& below,
             std::vector<Piece>& above) const {
    Mesh lower;
    Mesh upper;
    const SliceOutcome outcome = slicer_.slice(piece.mesh, plane, lower, upper, provenance_);
    if (outcome == SliceOutcome::failed) ++failed_cuts_;
    if (outcome != SliceOutcome::cut) return;
    append_parts(std::move(lower), below);
    append_parts(std::move(upper), above);
  }

  /// The volumes of `mesh` (each an outer shell with its cavities) as pieces.
  static void append_parts(Mesh&& mesh, std::vector<Piece>& out) {
    for (Mesh& part : volume_components(std::move(mesh))) {
      MassProperties mass = mass_properties(part);
      out.push_back({std::move(part), mass});
    }
  }

  /// Cuts the slicer could not cap; those pieces were kept whole.
  [[nodiscard]] int failed_cuts() const { return failed_cuts_; }

 private:
  CornerProvenance* provenance_;
  mutable MeshSlicer slicer_;
  mutable int failed_cuts_ = 0;
};

/// The solid's volumes as pieces: tracked by `provenance` when given.
std::vector<SliceKernel::Piece> start_pieces(const Mesh& solid, const CornerProvenance* provenance) {
  std::vector<SliceKernel::Piece> pieces;
  SliceKernel::append_parts(provenance != nullptr ? provenance->tracked() : Mesh(solid), pieces);
  return pieces;
}

Result<std::vector<Fragment>> to_fragments(std::vector<SliceKernel::Piece>&& pieces,
                                           const CornerProvenance* provenance) {
  std::vector<Fragment> out;
  out.reserve(pieces.size());
  for (SliceKernel::Piece& p : pieces) {
    if (provenance == nullptr) {
      out.push_back({std::move(p.mesh), p.mass});
      continue;
    }
    Result<Mesh> resolved = provenance->resolve(std::move(p.mesh));
    if (!resolved) return resolved.error();
    out.push_back({std::move(*resolved), p.mass});
  }
  return out;
}

/// The provenance records of one fracture of `solid`, when it carries attributes.
std::optional<CornerProvenance> provenance_for(const Mesh& solid) {
  if (!has_attributes(solid)) return std::nullopt;
  return std::optional<CornerProvenance>(std::in_place, solid, "plane-slice");
}

}  // namespace

Result<std::vector<Fragment>> PlaneSliceFracturer::fracture(const Mesh& solid,
                                                            const FractureParams& params) const {
  // The corner values are checked where the fragments read them (CornerProvenance::resolve).
  if (Status s = check_fracture_request(params, "plane-slice"); !s) return s.error();
  if (Status s = check_fracture_solid(solid, "plane-slice", params.verdicts, AttributeValues::at_use); !s)
    return s.error();
  std::optional<CornerProvenance> provenance = provenance_for(solid);
  CornerProvenance* tracking = provenance ? &*provenance : nullptr;
  const SliceKernel kernel(tracking);
  return to_fragments(slice_recursively(kernel, start_pieces(solid, tracking), params.fragments, params.seed),
                      tracking);
}

Result<std::vector<Fragment>> PlaneSliceFracturer::fracture_by_planes(const Mesh& solid, std::span<const Plane> planes,
                                                                      int max_fragments,
                                                                      SelfIntersectionVerdicts* verdicts) const {
  if (Status s = check_fracture_solid(solid, "plane-slice", verdicts, AttributeValues::at_use); !s)
    return s.error();
  if (Status s = check_planes(planes); !s) return s.error();
  std::optional<CornerProvenance> provenance = provenance_for(solid);
  CornerProvenance* tracking = provenance ? &*provenance : nullptr;
  const SliceKernel kernel(tracking);
  auto pieces = slice_by_planes(kernel, start_pieces(solid, tracking), planes,
                                static_cast<std::size_t>(std::max(max_fragments, 1)));
  if (!pieces) return Error{"plane-slice: " + pieces.error().message};
  return to_fragments(std::move(*pieces), tracking);
}

Result<std::optional<CutPlan>> PlaneSliceFracturer::cut_plan(const Mesh& solid, const FractureParams& params) const {
  if (Status s = check_fracture_params(solid, params, "plane-slice"); !s) return s.error();
  return std::optional<CutPlan>(RecursiveCutSchedule{params.fragments, params.seed});
}

void register_plane_slice(FracturerRegistry& registry) {
  registry.add("plane-slice", "recursive random plane cuts, constrained Delaunay caps (fast)", {},
               [](const PluginSettings& settings) -> Result<std::unique_ptr<Fracturer>> {
                 if (Status s = SettingsReader("plane-slice", settings, {}).check_keys(); !s) return s.error();
                 return std::unique_ptr<Fracturer>(std::make_unique<PlaneSliceFracturer>());
               });
}

}  // namespace shatter
