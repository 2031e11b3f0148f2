#include "algorithms/fracture/fem_lite/hex_grid.h"

#include "algorithms/core/winding_number.h"

#include <algorithm>
#include <cmath>

namespace shatter {

std::array<int, 3> hex_grid_counts(const Vec3& extent, int resolution) {
  const double target = extent.maxCoeff() / resolution;  // m, the nominal cell size
  std::array<int, 3> counts{};
  for (int a = 0; a < 3; ++a) counts[a] = std::max(2, static_cast<int>(std::lround(extent[a] / target)));
  return counts;
}

int budgeted_resolution(const Mesh& solid, int resolution, int max_cells) {
  if (max_cells <= 0) return resolution;
  const Aabb box = bounding_box(solid);
  const Vec3 extent = box.max - box.min;
  if (!(extent.maxCoeff() > 0.0)) return resolution;
  for (int r = resolution; r > 2; --r) {
    const std::array<int, 3> n = hex_grid_counts(extent, r);
    if (static_cast<std::int64_t>(n[0]) * n[1] * n[2] <= max_cells) return r;
  }
  return 2;
}

HexGrid build_hex_grid(const Mesh& solid, int resolution) {
  HexGrid grid;
  const Aabb box = bounding_box(solid);
  const Vec3 extent = box.max - box.min;
  const double longest = extent.maxCoeff();
  if (!(longest > 0.0)) return grid;
  const double target = longest / resolution;  // m, the nominal cell size
  grid.counts = hex_grid_counts(extent, resolution);
  for (int a = 0; a < 3; ++a) grid.cell[a] = extent[a] > 0.0 ? extent[a] / grid.counts[a] : target;
  grid.origin = box.min;

  const auto [nx, ny, nz] = grid.counts;
  const WindingNumberQuery inside(solid);
  const auto cell_index = [&](int i, int j, int k) { return (static_cast<std::size_t>(k) * ny + j) * nx + i; };
  const auto grid_node = [&](int i, int j, int k) {
    return (static_cast<std::size_t>(k) * (ny + 1) + j) * (nx + 1) + i;
  };
  // Kept cells in x-fastest order; cell -> kept index, -1 when outside.
  std::vector<std::int32_t> kept_id(static_cast<std::size_t>(nx) * ny * nz, -1);
  std::vector<std::array<int, 3>> kept;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const Vec3 centre = grid.origin + grid.cell.cwiseProduct(Vec3(i + 0.5, j + 0.5, k + 0.5));
        if (inside(centre) <= 0.5) continue;
        kept_id[cell_index(i, j, k)] = static_cast<std::int32_t>(kept.size());
        kept.push_back({i, j, k});
      }
  // Face-connected components (union-find): cells that touch only along an edge or at a corner are a
  // hinge, not a joint, so they get their own nodes and are solved as separate bodies.
  std::vector<std::int32_t> parent(kept.size());
  for (std::size_t c = 0; c < kept.size(); ++c) parent[c] = static_cast<std::int32_t>(c);
  const auto root = [&](std::int32_t c) {
    while (parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  };
  for (std::size_t c = 0; c < kept.size(); ++c) {
    const auto [i, j, k] = kept[c];
    for (const std::array<int, 3>& next : {std::array{i + 1, j, k}, std::array{i, j + 1, k}, std::array{i, j, k + 1}}) {
      if (next[0] >= nx || next[1] >= ny || next[2] >= nz) continue;
      const std::int32_t other = kept_id[cell_index(next[0], next[1], next[2])];
      if (other >= 0) parent[root(other)] = root(static_cast<std::int32_t>(c));
    }
  }
  std::vector<std::int32_t> label(kept.size(), -1);  // root -> component, in order of first cell
  std::vector<std::vector<std::size_t>> members;
  for (std::size_t c = 0; c < kept.size(); ++c) {
    std::int32_t& l = label[root(static_cast<std::int32_t>(c))];
    if (l < 0) {
      l = static_cast<std::int32_t>(members.size());
      members.emplace_back();
    }
    members[l].push_back(c);
  }
  // Nodes per component, in grid order; elements per component, in grid order.
  std::vector<std::int32_t> node_id((static_cast<std::size_t>(nx) + 1) * (ny + 1) * (nz + 1), -1);
  for (std::size_t m = 0; m < members.size(); ++m) {
    std::vector<std::size_t> used;
    for (std::size_t c : members[m])
      for (int corner = 0; corner < 8; ++corner)
        used.push_back(grid_node(kept[c][0] + (corner & 1), kept[c][1] + ((corner >> 1) & 1),
                                 kept[c][2] + ((corner >> 2) & 1)));
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    for (std::size_t g : used) {
      node_id[g] = static_cast<std::int32_t>(grid.nodes.size());
      const int i = static_cast<int>(g % (nx + 1));
      const int j = static_cast<int>(g / (nx + 1) % (ny + 1));
      const int k = static_cast<int>(g / ((static_cast<std::size_t>(nx) + 1) * (ny + 1)));
      grid.nodes.push_back(grid.origin + grid.cell.cwiseProduct(Vec3(i, j, k)));
      grid.node_component.push_back(static_cast<std::int32_t>(m));
    }
    for (std::size_t c : members[m]) {
      const auto [i, j, k] = kept[c];
      std::array<std::int32_t, 8> element{};
      for (int corner = 0; corner < 8; ++corner)
        element[corner] = node_id[grid_node(i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1))];
      grid.elements.push_back(element);
      grid.centres.push_back(grid.origin + grid.cell.cwiseProduct(Vec3(i + 0.5, j + 0.5, k + 0.5)));
    }
  }
  grid.component_count = static_cast<int>(members.size());
  return grid;
}

}  // namespace shatter
