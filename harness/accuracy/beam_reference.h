#pragma once
/// The analytic stress references: a case that is a box cut into slabs along one axis and held at one
/// end (cantilever, or column when the axis is vertical) or at both ends (fixed-fixed beam) has a
/// closed-form answer from beam theory; this file recognises such a case and rebuilds its structure at
/// any slab count.
///
/// Answers, with s the distance of a bond from the free end, w = rho g A the weight per length, and a
/// section of width b and height h (h along gravity):
/// - cantilever: M = w s^2 / 2, sigma = M c / I with c = h / 2, I = b h^3 / 12 (statically determinate);
/// - column: axial stress sigma = rho g s (rho g (H - z) measured from the base; determinate);
/// - fixed-fixed beam of span L: end moment w L^2 / 12, mid-span w L^2 / 24 (indeterminate: the
///   rigid-body-spring model approaches it as 1 / n^2 in the slab count n, docs/stress.md).

#include "algorithms/bonds/support_graph.h"
#include "algorithms/fracture/plane_cutting.h"
#include "algorithms/stress/stress_model.h"
#include "harness/cases/case.h"

#include <optional>
#include <vector>

namespace shatter {

/// Which closed-form answer a structure has.
enum class BeamKind { cantilever, column, fixed_beam };

/// A case recognised as an analytic beam or column.
struct BeamReference {
  BeamKind kind = BeamKind::cantilever;
  int axis = 0;                  ///< the slab axis (0 x, 1 y, 2 z)
  int gravity_axis = 2;          ///< the axis gravity acts along
  Vec3 size = Vec3::Ones();      ///< box edge lengths, m
  Vec3 center = Vec3::Zero();    ///< box centre, m
  bool anchored_at_min = true;   ///< cantilever and column: the held end is the low end of `axis`
  double density = 2400.0;       ///< kg/m^3
  double g = 9.81;               ///< |gravity|, m/s^2
};

/// The name of a kind: "cantilever", "column", "fixed-beam".
const char* beam_kind_name(BeamKind kind);

/// The reference of `c` when it is a box with explicit planes all normal to one axis, gravity along a
/// coordinate axis, and anchors only at the ends of that axis (one end: cantilever, or column when the
/// axis is along gravity and the held end is below; both ends, across gravity: fixed-fixed beam).
std::optional<BeamReference> classify_beam_case(const Case& c);

/// The structure of `ref` cut into `slabs` (>= 2) equal slabs. Cantilever and column: only the slab at
/// the held end is anchored. Fixed-fixed beam: the span is held by two thin anchored end blocks
/// (1e-5 of the span) so that the bonds at both ends are the clamped sections. The slabs are cut by
/// `cutter` (the case's plane_cutter, harness/plugins/capable_fracturer.h).
Result<SupportGraph> beam_structure(const BeamReference& ref, int slabs, const PlaneCutting& cutter);

/// Largest relative error of the bond results against the closed form: cantilever, bending moment and
/// peak normal stress at every bond; column, peak normal stress at every bond; fixed-fixed beam, the
/// moments at both ends and at mid-span (`slabs` even). NaN when a needed bond is missing.
double beam_error(const BeamReference& ref, const SupportGraph& graph, const StressResult& result);

/// The bonds where the closed form puts the largest stress (the correct first failure): the one next
/// to the held end of a cantilever or column, both end bonds of a fixed-fixed beam.
std::vector<int> beam_first_failure(const BeamReference& ref, const SupportGraph& graph);

}  // namespace shatter
