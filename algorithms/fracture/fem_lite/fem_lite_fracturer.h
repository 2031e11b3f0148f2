#pragma once
/// fem-lite: a coarse linear-elastic finite-element solve of the piece under the impact and gravity
/// (8-node bricks on a regular grid, sparse Cholesky in node blocks), crack planes through the most stressed
/// elements normal to their largest principal stress, the solid cut along them by the plane-slice
/// kernel. The planes are exposed so that the exact reference (cgal-clip) can replay them.

#include "algorithms/core/plane.h"
#include "algorithms/fracture/fem_lite/elastic_solve.h"
#include "algorithms/fracture/fem_lite/fem_lite_settings.h"
#include "algorithms/fracture/fracturer.h"
#include "algorithms/fracture/fracturer_registry.h"
#include "algorithms/fracture/plane_slice/slice_kernel.h"

#include <vector>

namespace shatter {

/// Everything one fem-lite analysis found, for reports and the documentation's measurements.
struct FemLiteAnalysis {
  std::vector<Plane> planes;     ///< crack planes, most stressed first (m; normals unit)
  int fragments = 0;             ///< fragments the planes cut the solid into
  /// The grid's resolution: the setting's, or lower under max_cells (and raised again, up to the
  /// setting's, until a cell centre lies inside the solid).
  int resolution = 0;
  int elements = 0;              ///< kept grid cells
  int nodes = 0;                 ///< grid nodes of the kept cells
  int over_strength = 0;         ///< elements whose largest principal stress exceeds the tensile strength
  double max_principal = 0.0;    ///< largest principal stress over the elements, Pa
  bool inertia_relief = false;   ///< true when the piece had no support (free-body solve)
  FemSolveReport solve;          ///< solver statistics (iterations, residual)
};

/// The fem-lite fracturer.
class FemLiteFracturer final : public Fracturer {
 public:
  /// A fracturer with the default settings (resolution 16, concrete, no gravity, no support).
  FemLiteFracturer() = default;
  /// A fracturer with the given settings (checked when fracturing).
  explicit FemLiteFracturer(FemLiteSettings settings) : settings_(std::move(settings)) {}
  [[nodiscard]] std::string_view name() const override { return "fem-lite"; }
  /// crack_planes() then PlaneSliceFracturer::fracture_by_planes: for a solid without attributes, the
  /// pieces the crack search cut (the same kernel, the same pieces in the same order) are the
  /// fragments, so the cuts are not made twice.
  [[nodiscard]] Result<std::vector<Fragment>> fracture(const Mesh& solid,
                                                       const FractureParams& params) const override;
  /// The crack planes (crack_planes()), cut in order.
  [[nodiscard]] Result<std::optional<CutPlan>> cut_plan(const Mesh& solid,
                                                        const FractureParams& params) const override;
  /// The crack planes of `solid` (closed, outward) under `params.impact` and gravity; cutting the
  /// solid by all of them (every piece each plane crosses) gives at least params.fragments fragments
  /// unless the grid runs out of candidate elements. Empty for one fragment.
  [[nodiscard]] Result<std::vector<Plane>> crack_planes(const Mesh& solid, const FractureParams& params) const;
  /// The full analysis behind crack_planes(). With `pieces`, it receives the pieces the planes cut the
  /// solid into: a plain mesh's, or an attributed solid's with their corners tracked through
  /// `provenance` (made for `solid`); an attributed solid without `provenance` gets none.
  [[nodiscard]] Result<FemLiteAnalysis> analyse(const Mesh& solid, const FractureParams& params,
                                                std::vector<SliceKernel::Piece>* pieces = nullptr,
                                                CornerProvenance* provenance = nullptr) const;
  /// The settings.
  [[nodiscard]] const FemLiteSettings& settings() const { return settings_; }

 private:
  FemLiteSettings settings_;
};

/// The documented settings of "fem-lite": the numeric fields of FemLiteSettings (the material,
/// gravity and supports are a program's, not a case's); `resolution` and `max_cells` are its accuracy knobs.
std::vector<SettingDoc> fem_lite_setting_docs();

/// FemLiteSettings (defaults, with the given keys) from user settings; an error names the key and range.
Result<FemLiteSettings> read_fem_lite_settings(const PluginSettings& settings);

/// Registers "fem-lite" (settings: fem_lite_setting_docs()).
void register_fem_lite(FracturerRegistry& registry);

}  // namespace shatter
