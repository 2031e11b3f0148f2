#include "algorithms/fracture/cgal_clip/cgal_clip_fracturer.h"

#include "algorithms/fracture/cgal_clip/cgal_exact_mesh.h"
#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/fracture/recursive_slicing.h"

#include <CGAL/Polygon_mesh_processing/clip.h>

#include <exception>
#include <stdexcept>
#include <memory>
#include <string>
#include <utility>
#include <vector>

// How a cut is done: PMP::clip(mesh, plane, clip_volume(true)) keeps the closed part on the negative
// side of the plane. It is run twice per cut, on two copies, once with the plane and once with its
// opposite, so both sides come out closed with their caps (PMP::split would leave them open, and
// closing them again would need a separate hole filling that knows nothing about the plane). The
// clipper is the bounding box cut by the plane, built with the kernel's exact constructions, so each
// cap lies exactly in the requested plane. Epeck is required: with inexact constructions, recursive
// clipping produces self-intersecting pieces that later clips refuse.
//
// Face tags travel as a face property "is_cut" on the Surface_mesh, maintained by a corefinement
// visitor: a face split by the clip inherits the flag of the face it came from, a face copied from the
// clipper (the cap) is a cut face, untouched faces keep their flag.

namespace shatter {
namespace {

using namespace cgal_exact;

/// The slicing kernel of recursive_slicing.h over exact CGAL clipping.
class ExactClipKernel {
 public:
  /// One connected closed piece (cgal_exact_mesh.h).
  using Piece = cgal_exact::Piece;

  /// Volume centroid of the piece, m (from double approximations; accurate to round-off).
  [[nodiscard]] Vec3 centroid(const Piece& piece) const { return piece.centroid; }

  /// Appends the closed connected parts of `piece` below (dot(normal, x - point) < 0) and above the
  /// plane; appends nothing when the plane leaves the whole piece on one side.
  void split(const Piece& piece, const Plane& plane, std::vector<Piece>& below,
             std::vector<Piece>& above) const {
    const ExactPlane cut = exact_plane(plane.point, plane.normal);
    // Exact side test first: a plane that leaves every vertex on one side (or on it) does not cut the
    // piece in two, and clipping such a touching plane is a degenerate case better not asked of CGAL.
    bool any_below = false;
    bool any_above = false;
    for (VertexIndex v : piece.mesh.vertices()) {
      const CGAL::Oriented_side side = cut.oriented_side(piece.mesh.point(v));
      any_below = any_below || side == CGAL::ON_NEGATIVE_SIDE;
      any_above = any_above || side == CGAL::ON_POSITIVE_SIDE;
      if (any_below && any_above) break;
    }
    if (!any_below || !any_above) return;
    clip_into(piece.mesh, cut, below);
    clip_into(piece.mesh, cut.opposite(), above);
  }

 private:
  /// Clips a copy of `mesh` to the negative side of `plane` and appends its parts.
  static void clip_into(const SurfaceMesh& mesh, const ExactPlane& plane, std::vector<Piece>& out) {
    SurfaceMesh part = mesh;
    TagState state = tag_state(part);
    ClipTagVisitor visitor;
    visitor.state = &state;
    const bool manifold =
        PMP::clip(part, plane, CGAL::parameters::clip_volume(true).visitor(visitor));
    if (!manifold) throw ClipFailure("a clip gave a non-manifold result (parts touching at a vertex or edge)");
    append_parts(std::move(part), out);
  }
};

/// The input solid as exact pieces (its connected parts); input tags are kept, so a fragment
/// fractured again keeps its earlier cut faces tagged cut.
std::vector<ExactClipKernel::Piece> start_pieces(const Mesh& solid) {
  std::vector<ExactClipKernel::Piece> pieces;
  append_parts(exact_solid(solid), pieces);
  return pieces;
}

/// Runs `schedule` on the exact pieces of `solid` and converts the result; CGAL failures become errors.
template <class Schedule>
Result<std::vector<Fragment>> run(const Mesh& solid, Schedule&& schedule) {
  try {
    std::vector<ExactClipKernel::Piece> pieces = schedule(ExactClipKernel{}, start_pieces(solid));
    std::vector<Fragment> fragments;
    fragments.reserve(pieces.size());
    for (ExactClipKernel::Piece& piece : pieces) fragments.push_back(to_fragment(piece, solid));
    return fragments;
  } catch (const std::exception& e) {
    return Error{std::string("cgal-clip: ") + e.what()};
  }
}

}  // namespace

Status check_reference_size(std::size_t count, const char* what) {
  if (count <= static_cast<std::size_t>(kMaxReferenceFragments)) return {};
  return Error{"cgal-clip: at most " + std::to_string(kMaxReferenceFragments) + " " + what +
               " (the exact reference would run for minutes), got " + std::to_string(count)};
}

Result<std::vector<Fragment>> CgalClipFracturer::fracture(const Mesh& solid, const FractureParams& params) const {
  if (Status s = check_fracture_params(solid, params, "cgal-clip"); !s) return s.error();
  if (Status s = check_reference_size(static_cast<std::size_t>(params.fragments), "fragments"); !s) return s.error();
  return run(solid, [&](const ExactClipKernel& kernel, std::vector<ExactClipKernel::Piece> start) {
    return slice_recursively(kernel, std::move(start), params.fragments, params.seed);
  });
}

Result<std::vector<Fragment>> CgalClipFracturer::cut_by_planes(const Mesh& solid,
                                                               std::span<const Plane> planes) const {
  return fracture_by_planes(solid, planes);
}

Result<std::vector<Fragment>> CgalClipFracturer::fracture_by_planes(const Mesh& solid,
                                                                    std::span<const Plane> planes) const {
  if (Status s = check_fracture_solid(solid, "cgal-clip", nullptr); !s) return s.error();
  if (Status s = check_planes(planes); !s) return s.error();
  // n planes can make up to about n + 1 pieces of a convex solid, more of a non-convex one.
  if (Status s = check_reference_size(planes.size(), "planes"); !s) return s.error();
  return run(solid, [&](const ExactClipKernel& kernel, std::vector<ExactClipKernel::Piece> start) {
    auto pieces = slice_by_planes(kernel, std::move(start), planes, static_cast<std::size_t>(kMaxFragments));
    if (!pieces) throw std::runtime_error(pieces.error().message);
    return std::move(*pieces);
  });
}

Result<std::vector<Fragment>> CgalClipFracturer::replay(const Mesh& solid, const CutPlan& plan) const {
  if (const auto* schedule = std::get_if<RecursiveCutSchedule>(&plan)) {
    FractureParams params;
    params.fragments = schedule->fragments;
    params.seed = schedule->seed;
    return fracture(solid, params);
  }
  if (const auto* planes = std::get_if<PlaneCuts>(&plan)) return fracture_by_planes(solid, planes->planes);
  return fracture_by_cells(solid, std::get<CellCuts>(plan).cells);
}

void register_cgal_clip(FracturerRegistry& registry) {
  registry.add("cgal-clip", "the plane-slice cut schedule done by exact CGAL clipping (reference, slow)", {},
               [](const PluginSettings& settings) -> Result<std::unique_ptr<Fracturer>> {
                 if (Status s = SettingsReader("cgal-clip", settings, {}).check_keys(); !s) return s.error();
                 return std::unique_ptr<Fracturer>(std::make_unique<CgalClipFracturer>());
               });
}

}  // namespace shatter
