#pragma once
/// voronoi: sites inside the solid (uniform, or clustered around the impact), each site's Voronoi cell
/// cut out of the solid by its bisector planes with the slicing kernel (MeshSlicer), disconnected
/// parts of a cell split into their own fragments.

#include "algorithms/fracture/fracturer.h"
#include "algorithms/fracture/fracturer_registry.h"
#include "algorithms/fracture/voronoi/voronoi_sites.h"

#include <span>

namespace shatter {

/// Settings of the voronoi fracturer (plain data; every field has a default).
struct VoronoiSettings {
  /// Where the sites go (impact share, draw budget).
  SiteSettings sites;
  /// Cells per leaf of the site tree: below this many, cells are cut from their node's piece
  /// directly (>= 1; default 1). Larger values trade tree cuts for longer bisector sequences.
  int leaf_cells = 1;
};

/// The voronoi fracturer: one fragment per connected part of each site's cell inside the solid.
class VoronoiFracturer final : public Fracturer {
 public:
  /// A fracturer with the given settings (checked when fracturing).
  explicit VoronoiFracturer(VoronoiSettings settings = {}) : settings_(settings) {}
  [[nodiscard]] std::string_view name() const override { return "voronoi"; }
  /// Places `params.fragments` sites (voronoi_sites.h) and cuts `solid` into their cells. A solid
  /// whose surface intersects itself is an error (its cut outlines would cross).
  [[nodiscard]] Result<std::vector<Fragment>> fracture(const Mesh& solid,
                                                       const FractureParams& params) const override;
  /// The bisector cells of the sites fracture() places (one cell per site, in site order).
  [[nodiscard]] Result<std::optional<CutPlan>> cut_plan(const Mesh& solid,
                                                        const FractureParams& params) const override;
  /// Cuts `solid` into the Voronoi cells of the given sites (#S distinct finite points, m; sites
  /// outside the solid are allowed, their cells may miss it). Fragments come in site order, the parts
  /// of one cell in connected_components order; cells that miss the solid give none. A solid whose
  /// surface intersects itself is an error (tested on every call: no verdicts are remembered).
  [[nodiscard]] Result<std::vector<Fragment>> fracture_with_sites(const Mesh& solid,
                                                                  std::span<const Vec3> sites) const;

 private:
  /// The cells of checked `sites` cut out of `solid`; `inside` is its inside test, or null.
  [[nodiscard]] std::vector<Fragment> cut_cells(const Mesh& solid, std::span<const Vec3> sites,
                                                const PointInMesh* inside) const;
  VoronoiSettings settings_;
};

/// The documented settings of "voronoi" (the fields of VoronoiSettings).
std::vector<SettingDoc> voronoi_setting_docs();

/// VoronoiSettings from user settings; an error names the key and its range.
Result<VoronoiSettings> read_voronoi_settings(const PluginSettings& settings);

/// Registers "voronoi" (settings: voronoi_setting_docs()).
void register_voronoi(FracturerRegistry& registry);

}  // namespace shatter
