#include "algorithms/fracture/fem_lite/fem_lite_fracturer.h"

#include "algorithms/fracture/fem_lite/crack_plane_search.h"
#include "algorithms/fracture/fem_lite/element_stress.h"
#include "algorithms/fracture/fem_lite/fem_loads.h"
#include "algorithms/fracture/fem_lite/hex_grid.h"
#include "algorithms/fracture/fracture_limits.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <string>

namespace shatter {

Result<FemLiteAnalysis> FemLiteFracturer::analyse(const Mesh& solid, const FractureParams& params,
                                                  std::vector<SliceKernel::Piece>* pieces,
                                                  CornerProvenance* provenance) const {
  if (Status s = check_fracture_params(solid, params, "fem-lite"); !s) return s.error();
  if (Status s = check_fem_lite_settings(settings_); !s) return s.error();
  FemLiteAnalysis analysis;
  if (params.fragments <= 1) {
    analysis.fragments = 1;
    return analysis;
  }
  analysis.resolution = budgeted_resolution(solid, settings_.resolution, settings_.max_cells);
  HexGrid grid = build_hex_grid(solid, analysis.resolution);
  // A piece thinner than the budgeted grid's cells (a wall of a hollow frame) has no cell centre inside
  // it: the next finer grids, up to the setting's resolution, until one has.
  while (grid.elements.empty() && analysis.resolution < settings_.resolution)
    grid = build_hex_grid(solid, ++analysis.resolution);
  analysis.elements = static_cast<int>(grid.elements.size());
  analysis.nodes = static_cast<int>(grid.nodes.size());
  if (grid.elements.empty())
    return Error{"fem-lite: no grid cell centre lies inside the solid at resolution " +
                 std::to_string(analysis.resolution) + " (raise the resolution)"};
  Result<FemLoads> loads = fem_loads(grid, settings_, params.impact);
  if (!loads) return loads.error();
  analysis.inertia_relief = loads->inertia_relief;
  Result<FemSolution> solution = solve_elastic(grid, settings_.material, *loads);
  if (!solution) return solution.error();
  analysis.solve = solution->report;
  const std::vector<ElementStress> stresses = element_stresses(grid, settings_.material, solution->displacements);
  analysis.max_principal = stresses.empty() ? 0.0 : stresses[0].max_principal;
  for (const ElementStress& s : stresses) analysis.max_principal = std::max(analysis.max_principal, s.max_principal);

  CrackSearchOptions options;
  options.fragments = params.fragments;
  options.spacing = settings_.crack_spacing;
  options.tensile_strength = settings_.material.tensile_strength;
  options.seed = params.seed;
  options.min_piece_share = settings_.min_piece_share;
  // An attributed solid's pieces are only of use with their corners tracked.
  const bool tracked = has_attributes(solid);
  if (tracked && provenance == nullptr) pieces = nullptr;
  CrackSearch search = search_crack_planes(solid, grid, stresses, options, pieces, tracked ? provenance : nullptr);
  analysis.planes = std::move(search.planes);
  analysis.fragments = search.fragments;
  analysis.over_strength = search.over_strength;
  return analysis;
}

Result<std::vector<Plane>> FemLiteFracturer::crack_planes(const Mesh& solid, const FractureParams& params) const {
  Result<FemLiteAnalysis> analysis = analyse(solid, params);
  if (!analysis) return analysis.error();
  return std::move(analysis->planes);
}

Result<std::vector<Fragment>> FemLiteFracturer::fracture(const Mesh& solid, const FractureParams& params) const {
  // An attributed solid's corners are tracked through the search's cuts, as fracture_by_planes tracks
  // them (the values are read, and checked, when the fragments are made).
  std::optional<CornerProvenance> provenance;
  if (has_attributes(solid)) provenance.emplace(solid, "fem-lite");
  CornerProvenance* tracking = provenance ? &*provenance : nullptr;
  std::vector<SliceKernel::Piece> pieces;
  Result<FemLiteAnalysis> analysis = analyse(solid, params, &pieces, tracking);
  if (!analysis) return analysis.error();
  // The search's pieces are fracture_by_planes' fragments; it runs itself for what the search did not
  // cut (one fragment) and for its own error past the fragment limit.
  if (!pieces.empty() && pieces.size() <= static_cast<std::size_t>(kMaxFragments))
    return to_fragments(std::move(pieces), tracking);
  // The crack planes are the search's choice: one the kernel cannot cap leaves its piece whole, as
  // the search's own count of pieces assumed (piece_counter.h).
  return PlaneSliceFracturer().fracture_by_planes(solid, analysis->planes, kMaxFragments, params.verdicts,
                                                  PlaneSliceFracturer::FailedCut::keep_whole);
}

Result<std::optional<CutPlan>> FemLiteFracturer::cut_plan(const Mesh& solid, const FractureParams& params) const {
  Result<std::vector<Plane>> planes = crack_planes(solid, params);
  if (!planes) return planes.error();
  return std::optional<CutPlan>(PlaneCuts{std::move(*planes)});
}

std::vector<SettingDoc> fem_lite_setting_docs() {
  return {{"resolution", "cells", "16", "[2, " + std::to_string(kFemLiteMaxResolution) + "]",
           "grid cells along the longest axis of the solid's box", {8, 16, 32}},
          {"max_cells", "cells", "0", "[0, " + std::to_string(kFemLiteMaxCells) + "]",
           "most grid cells over the solid's box; the resolution is lowered to fit (0: no budget)", {125, 512}},
          {"contact_time", "s", "0.0166667", "(0, 1e6]", "contact time of the impact: force = impulse / time", {}},
          {"crack_spacing", "cells", "1", "[0, 1e6]", "least distance of a new crack from an earlier plane", {}},
          {"min_piece_share", "", "0.01", "[0, 0.99]", "least piece a crack may cut off, share of the mean", {}}};
}

Result<FemLiteSettings> read_fem_lite_settings(const PluginSettings& settings) {
  const std::vector<SettingDoc> docs = fem_lite_setting_docs();
  const SettingsReader r("fem-lite", settings, docs);
  FemLiteSettings f;
  if (Status s = r.check_keys(); !s) return s.error();
  if (Status s = r.integer("resolution", 2, kFemLiteMaxResolution, f.resolution); !s) return s.error();
  if (Status s = r.integer("max_cells", 0, kFemLiteMaxCells, f.max_cells); !s) return s.error();
  if (Status s = r.number_above("contact_time", 0.0, 1e6, f.contact_time); !s) return s.error();
  if (Status s = r.number("crack_spacing", 0.0, 1e6, f.crack_spacing); !s) return s.error();
  if (Status s = r.number("min_piece_share", 0.0, 0.99, f.min_piece_share); !s) return s.error();
  return f;
}

void register_fem_lite(FracturerRegistry& registry) {
  registry.add("fem-lite", "crack planes from a coarse linear-elastic FEM solve under the impact, plane-slice cuts",
               fem_lite_setting_docs(), [](const PluginSettings& settings) -> Result<std::unique_ptr<Fracturer>> {
                 Result<FemLiteSettings> f = read_fem_lite_settings(settings);
                 if (!f) return f.error();
                 return std::unique_ptr<Fracturer>(std::make_unique<FemLiteFracturer>(std::move(*f)));
               });
}

}  // namespace shatter
