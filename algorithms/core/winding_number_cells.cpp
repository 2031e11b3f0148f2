#include "algorithms/core/winding_number_cells.h"

#include <algorithm>
#include <cmath>

namespace shatter {
namespace {

constexpr std::int32_t kMarked = -1;
constexpr std::int32_t kUnlabelled = -2;

}  // namespace

WindingNumberCells::WindingNumberCells(const Mesh& mesh) : tree_(mesh) {
  const std::size_t n = mesh.triangles.size();
  if (n < kMinTriangles || !tree_.closed()) return;
  const Aabb& box = tree_.bounds();
  const Vec3 size = box.max - box.min;
  // About one cell per triangle, at most 1024 along an axis.
  double cell = std::cbrt(std::max(size.x(), 1e-300) * std::max(size.y(), 1e-300) * std::max(size.z(), 1e-300) /
                          static_cast<double>(n));
  cell = std::max(cell, size.maxCoeff() / 1024.0);
  if (!(cell > 0.0) || !std::isfinite(cell)) return;
  std::array<int, 3> dims;
  for (int k = 0; k < 3; ++k) dims[k] = std::clamp(static_cast<int>(std::ceil(size[k] / cell)), 1, 1024);
  const auto cells = static_cast<std::size_t>(dims[0]) * static_cast<std::size_t>(dims[1]) * static_cast<std::size_t>(dims[2]);
  if (cells > 4 * n + 64) return;
  const auto coordinate = [&](double x, int k) {
    return std::clamp(static_cast<int>(std::floor((x - box.min[k]) / cell)), 0, dims[k] - 1);
  };
  // Each triangle's cells, with a margin of one; a mesh of long triangles that would mark far more
  // cells than the grid has is left to the tree.
  std::vector<std::array<int, 6>> ranges(n);
  double marks = 0.0;
  for (std::size_t f = 0; f < n; ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh.vertices[static_cast<std::size_t>(t[2])];
    const Vec3 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    double volume = 1.0;
    for (int k = 0; k < 3; ++k) {
      ranges[f][k] = std::max(coordinate(lo[k], k) - 1, 0);
      ranges[f][k + 3] = std::min(coordinate(hi[k], k) + 1, dims[k] - 1);
      volume *= ranges[f][k + 3] - ranges[f][k] + 1;
    }
    marks += volume;
  }
  if (marks > 64.0 * static_cast<double>(cells)) return;

  const auto index = [&](int x, int y, int z) {
    return (static_cast<std::size_t>(z) * static_cast<std::size_t>(dims[1]) + static_cast<std::size_t>(y)) *
               static_cast<std::size_t>(dims[0]) + static_cast<std::size_t>(x);
  };
  std::vector<std::int32_t> label(cells, kUnlabelled);
  for (const std::array<int, 6>& r : ranges)
    for (int z = r[2]; z <= r[5]; ++z)
      for (int y = r[1]; y <= r[4]; ++y)
        for (int x = r[0]; x <= r[3]; ++x) label[index(x, y, z)] = kMarked;
  ranges = {};

  // 6-connected regions of unmarked cells, by breadth-first search.
  std::vector<std::int32_t> queue;
  std::vector<std::int32_t> region_size;
  std::vector<std::size_t> region_first;
  for (std::size_t start = 0; start < cells; ++start) {
    if (label[start] != kUnlabelled) continue;
    const auto region = static_cast<std::int32_t>(region_size.size());
    region_size.push_back(0);
    region_first.push_back(start);
    queue.assign(1, static_cast<std::int32_t>(start));
    label[start] = region;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const auto c = static_cast<std::size_t>(queue[head]);
      ++region_size.back();
      const int x = static_cast<int>(c % static_cast<std::size_t>(dims[0]));
      const int y = static_cast<int>(c / static_cast<std::size_t>(dims[0]) % static_cast<std::size_t>(dims[1]));
      const int z = static_cast<int>(c / (static_cast<std::size_t>(dims[0]) * static_cast<std::size_t>(dims[1])));
      const auto visit = [&](int vx, int vy, int vz) {
        if (vx < 0 || vy < 0 || vz < 0 || vx >= dims[0] || vy >= dims[1] || vz >= dims[2]) return;
        std::int32_t& l = label[index(vx, vy, vz)];
        if (l != kUnlabelled) return;
        l = region;
        queue.push_back(static_cast<std::int32_t>(index(vx, vy, vz)));
      };
      visit(x - 1, y, z), visit(x + 1, y, z), visit(x, y - 1, z), visit(x, y + 1, z), visit(x, y, z - 1), visit(x, y, z + 1);
    }
  }
  // One exact query per region large enough; smaller regions go to the tree.
  std::vector<std::int32_t> kept(region_size.size(), -1);
  for (std::size_t r = 0; r < region_size.size(); ++r) {
    if (region_size[r] < kMinRegionCells) continue;
    const std::size_t c = region_first[r];
    const Vec3 centre(box.min.x() + (static_cast<double>(c % static_cast<std::size_t>(dims[0])) + 0.5) * cell,
                      box.min.y() + (static_cast<double>(c / static_cast<std::size_t>(dims[0]) % static_cast<std::size_t>(dims[1])) + 0.5) * cell,
                      box.min.z() + (static_cast<double>(c / (static_cast<std::size_t>(dims[0]) * static_cast<std::size_t>(dims[1]))) + 0.5) * cell);
    kept[r] = static_cast<std::int32_t>(region_value_.size());
    region_value_.push_back(tree_(centre));
  }
  for (std::int32_t& l : label) l = l >= 0 ? kept[static_cast<std::size_t>(l)] : -1;
  region_of_cell_ = std::move(label);
  dims_ = dims;
  origin_ = box.min;
  cell_ = cell;
}

std::int64_t WindingNumberCells::cell_of(const Vec3& q) const {
  if (region_of_cell_.empty()) return -1;
  std::int64_t c = 0;
  for (int k = 2; k >= 0; --k) {
    const int i = std::clamp(static_cast<int>(std::floor((q[k] - origin_[k]) / cell_)), 0, dims_[k] - 1);
    c = c * dims_[k] + i;
  }
  return c;
}

bool WindingNumberCells::answered_by_cells(const Vec3& q) const {
  if (!bounds().contains(q)) return false;
  const std::int64_t c = cell_of(q);
  return c >= 0 && region_of_cell_[static_cast<std::size_t>(c)] >= 0;
}

double WindingNumberCells::operator()(const Vec3& q) const {
  if (!bounds().contains(q)) return 0.0;
  if (const std::int64_t c = cell_of(q); c >= 0) {
    const std::int32_t region = region_of_cell_[static_cast<std::size_t>(c)];
    if (region >= 0) return region_value_[static_cast<std::size_t>(region)];
  }
  return tree_(q);
}

}  // namespace shatter
