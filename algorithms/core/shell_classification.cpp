#include "algorithms/core/shell_classification.h"

#include "algorithms/core/self_intersection.h"
#include "algorithms/core/winding_number.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numeric>
#include <optional>

namespace shatter {
namespace {

/// Union-find root of `v`, with path halving.
std::int32_t root_of(std::vector<std::int32_t>& parent, std::int32_t v) {
  while (parent[static_cast<std::size_t>(v)] != v) {
    parent[static_cast<std::size_t>(v)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
    v = parent[static_cast<std::size_t>(v)];
  }
  return v;
}

/// The shell of every triangle (numbered in the order of their first triangle) and the shells.
std::vector<std::int32_t> split_shells(const Mesh& mesh, std::vector<Shell>& shells) {
  std::vector<std::int32_t> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const Triangle& t : mesh.triangles)
    for (int i = 1; i < 3; ++i) {
      const std::int32_t a = root_of(parent, t[0]), b = root_of(parent, t[i]);
      if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    }
  std::vector<std::int32_t> shell_of_root(mesh.vertices.size(), -1);
  std::vector<std::int32_t> shell_of(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    std::int32_t& shell = shell_of_root[static_cast<std::size_t>(root_of(parent, mesh.triangles[f][0]))];
    if (shell < 0) {
      shell = static_cast<std::int32_t>(shells.size());
      shells.emplace_back();
    }
    shell_of[f] = shell;
    shells[static_cast<std::size_t>(shell)].triangles.push_back(static_cast<std::int32_t>(f));
  }
  return shell_of;
}

/// Signed volume of each shell, m^3, summed about the mesh's box centre (less cancellation).
void measure_volumes(const Mesh& mesh, std::vector<Shell>& shells) {
  const Aabb box = bounding_box(mesh);
  const Vec3 origin = 0.5 * (box.min + box.max);
  for (Shell& shell : shells) {
    double six_volume = 0.0;
    for (const std::int32_t f : shell.triangles) {
      const Triangle& t = mesh.triangles[static_cast<std::size_t>(f)];
      const Vec3 a = mesh.vertices[static_cast<std::size_t>(t[0])] - origin;
      const Vec3 b = mesh.vertices[static_cast<std::size_t>(t[1])] - origin;
      const Vec3 c = mesh.vertices[static_cast<std::size_t>(t[2])] - origin;
      six_volume += a.dot(b.cross(c));
    }
    shell.volume = six_volume / 6.0;
  }
}

/// Bounding box of each shell, m.
std::vector<Aabb> shell_boxes(const Mesh& mesh, const std::vector<Shell>& shells) {
  std::vector<Aabb> box(shells.size());
  for (std::size_t s = 0; s < shells.size(); ++s)
    for (const std::int32_t f : shells[s].triangles)
      for (const std::int32_t v : mesh.triangles[static_cast<std::size_t>(f)]) box[s].extend(mesh.vertices[static_cast<std::size_t>(v)]);
  return box;
}

/// True when two of the boxes overlap (closed boxes: touching counts). Sweep and prune along the
/// axis on which the boxes spread most, stopping at the first overlap: shells whose boxes are
/// pairwise apart can neither cross nor hold one another, the common case of a mesh of separate parts.
bool any_boxes_overlap(const std::vector<Aabb>& box) {
  Aabb centres;
  for (const Aabb& b : box) centres.extend(0.5 * (b.min + b.max));
  int axis = 0;
  (centres.max - centres.min).maxCoeff(&axis);
  std::vector<std::int32_t> order(box.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
    return box[static_cast<std::size_t>(a)].min[axis] < box[static_cast<std::size_t>(b)].min[axis];
  });
  std::vector<std::int32_t> active;
  for (const std::int32_t i : order) {
    const Aabb& b = box[static_cast<std::size_t>(i)];
    std::erase_if(active, [&](std::int32_t j) { return box[static_cast<std::size_t>(j)].max[axis] < b.min[axis]; });
    for (const std::int32_t j : active) {
      const Aabb& a = box[static_cast<std::size_t>(j)];
      if ((a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all()) return true;
    }
    active.push_back(i);
  }
  return false;
}

/// The shell's triangles as a mesh of their own (only the vertices they use). `scratch` holds -1
/// per vertex of `mesh` on entry and on return.
Mesh shell_mesh(const Mesh& mesh, const Shell& shell, std::vector<std::int32_t>& scratch) {
  Mesh out;
  for (const std::int32_t f : shell.triangles) {
    Triangle t = mesh.triangles[static_cast<std::size_t>(f)];
    for (std::int32_t& v : t) {
      std::int32_t& mapped = scratch[static_cast<std::size_t>(v)];
      if (mapped < 0) mapped = out.add_vertex(mesh.vertices[static_cast<std::size_t>(v)]);
      v = mapped;
    }
    out.add_triangle(t[0], t[1], t[2], FaceTag::surface);
  }
  for (const std::int32_t f : shell.triangles)
    for (const std::int32_t v : mesh.triangles[static_cast<std::size_t>(f)]) scratch[static_cast<std::size_t>(v)] = -1;
  return out;
}

/// Sets every shell's innermost container. A point of each shell (the centroid of its first
/// triangle, on no other shell because no two shells cross) is bucketed in a uniform grid of about
/// one point per cell; each shell tests, by winding number, the points in the cells its box covers.
void find_containers(const Mesh& mesh, const std::vector<Aabb>& box, std::vector<Shell>& shells) {
  const std::size_t k = shells.size();
  std::vector<Vec3> point(k);
  Aabb all;
  for (std::size_t s = 0; s < k; ++s) {
    const Triangle& t = mesh.triangles[static_cast<std::size_t>(shells[s].triangles.front())];
    point[s] = (mesh.vertices[static_cast<std::size_t>(t[0])] + mesh.vertices[static_cast<std::size_t>(t[1])] +
                mesh.vertices[static_cast<std::size_t>(t[2])]) /
               3.0;
    all.extend(point[s]);
  }
  const int n = std::max(1, static_cast<int>(std::ceil(std::cbrt(static_cast<double>(k)))));
  const Vec3 size = all.max - all.min;
  const auto coordinate = [&](double x, int axis) {
    if (!(size[axis] > 0.0)) return 0;
    const double cell = std::floor((x - all.min[axis]) / size[axis] * n);
    return static_cast<int>(std::clamp(cell, 0.0, static_cast<double>(n - 1)));
  };
  const auto index = [n](int x, int y, int z) { return (static_cast<std::size_t>(z) * n + y) * n + x; };
  const std::size_t cells = static_cast<std::size_t>(n) * n * n;
  std::vector<std::int32_t> start(cells + 1, 0), member(k);
  std::vector<std::size_t> cell_of(k);
  for (std::size_t s = 0; s < k; ++s) {
    cell_of[s] = index(coordinate(point[s].x(), 0), coordinate(point[s].y(), 1), coordinate(point[s].z(), 2));
    ++start[cell_of[s] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
  std::vector<std::int32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t s = 0; s < k; ++s) member[static_cast<std::size_t>(fill[cell_of[s]]++)] = static_cast<std::int32_t>(s);

  std::vector<std::int32_t> scratch(mesh.vertices.size(), -1);
  for (std::size_t j = 0; j < k; ++j) {
    std::optional<WindingNumberQuery> inside;  // built when a point first falls in the box
    std::array<int, 3> low{}, high{};
    for (int axis = 0; axis < 3; ++axis) {
      low[axis] = coordinate(box[j].min[axis], axis);
      high[axis] = coordinate(box[j].max[axis], axis);
    }
    for (int z = low[2]; z <= high[2]; ++z)
      for (int y = low[1]; y <= high[1]; ++y)
        for (int x = low[0]; x <= high[0]; ++x) {
          const std::size_t c = index(x, y, z);
          for (std::int32_t m = start[c]; m < start[c + 1]; ++m) {
            const auto i = static_cast<std::size_t>(member[static_cast<std::size_t>(m)]);
            if (i == j || !box[j].contains(point[i])) continue;
            if (!inside) inside.emplace(shell_mesh(mesh, shells[j], scratch));
            if (std::abs((*inside)(point[i])) <= 0.5) continue;
            int& container = shells[i].container;  // the innermost container is the smallest
            if (container < 0 || std::abs(shells[j].volume) < std::abs(shells[static_cast<std::size_t>(container)].volume))
              container = static_cast<int>(j);
          }
        }
  }
}

/// The verdict on shells that do not cross, orientations read reversed when `inverted`.
void judge(ShellClassification& c) {
  const auto outward = [&](int s) { return c.shells[static_cast<std::size_t>(s)].outward() != c.inverted; };
  bool nested = false;
  for (int s = 0; s < static_cast<int>(c.shells.size()); ++s) {
    const int container = c.shells[static_cast<std::size_t>(s)].container;
    if (container < 0 && !outward(s)) {
      c.verdict = SolidVerdict::invalid;
      c.reason = "shells of mixed orientation: " + shell_name(c, s) + " faces inward and lies inside no other shell";
      return;
    }
    if (container >= 0 && outward(s) == outward(container)) {
      c.verdict = SolidVerdict::invalid;
      c.reason = "nested shells of one orientation: " + shell_name(c, s) + " lies inside " + shell_name(c, container) +
                 " and faces the same way (its volume would count twice)";
      return;
    }
    nested = nested || container >= 0;
  }
  if (!nested) return;
  for (int s = 0; s < static_cast<int>(c.shells.size()); ++s) {
    const int container = c.shells[static_cast<std::size_t>(s)].container;
    if (container < 0) continue;
    c.verdict = SolidVerdict::with_cavities;
    c.reason = (outward(s) ? shell_name(c, s) + " is an island in the cavity " + shell_name(c, container)
                           : shell_name(c, s) + " is a cavity inside " + shell_name(c, container));
    return;
  }
}

}  // namespace

ShellClassification classify_shells(const Mesh& mesh) {
  ShellClassification c;
  if (mesh.triangles.empty()) return c;
  const std::vector<std::int32_t> shell_of = split_shells(mesh, c.shells);
  measure_volumes(mesh, c.shells);
  const std::vector<Aabb> boxes = c.shells.size() > 1 ? shell_boxes(mesh, c.shells) : std::vector<Aabb>{};
  if (c.shells.size() > 1 && any_boxes_overlap(boxes)) {
    if (const auto pair = find_intersection_between_parts(mesh, shell_of)) {
      c.verdict = SolidVerdict::invalid;
      c.reason = "shells cross: " + shell_name(c, shell_of[static_cast<std::size_t>((*pair)[0])]) + " and " +
                 shell_name(c, shell_of[static_cast<std::size_t>((*pair)[1])]) + " intersect (triangles " +
                 std::to_string((*pair)[0]) + " and " + std::to_string((*pair)[1]) + ")";
      return c;
    }
    find_containers(mesh, boxes, c.shells);
  }
  c.inverted = std::all_of(c.shells.begin(), c.shells.end(), [](const Shell& s) { return s.container >= 0 || !s.outward(); });
  judge(c);
  return c;
}

std::string shell_name(const ShellClassification& shells, int index) {
  const Shell& s = shells.shells[static_cast<std::size_t>(index)];
  return "shell " + std::to_string(index) + " (" + std::to_string(s.triangles.size()) + " triangles from triangle " +
         std::to_string(s.triangles.front()) + ")";
}

}  // namespace shatter
