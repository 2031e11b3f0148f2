#include "algorithms/core/pinched_vertices.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

namespace shatter {
namespace {

std::int32_t find(std::vector<std::int32_t>& parent, std::int32_t x) {
  while (parent[static_cast<std::size_t>(x)] != x) {
    parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    x = parent[static_cast<std::size_t>(x)];
  }
  return x;
}

/// Pairs the halfedges (corner c = 3 t + k: triangles[t][k] -> triangles[t][k + 1]) of the undirected
/// edge lo < hi into sheets (design note) and writes each one's twin. False when their directions do
/// not alternate by angle (or two half-planes coincide), which no solid has.
bool pair_around_edge(const Mesh& mesh, std::int32_t lo, std::int32_t hi, const std::vector<std::int32_t>& uses,
                      std::vector<std::int32_t>& twin) {
  const Vec3& a = mesh.vertices[static_cast<std::size_t>(lo)];
  const Vec3 d = (mesh.vertices[static_cast<std::size_t>(hi)] - a).normalized();
  const Vec3 x = d.unitOrthogonal();
  const Vec3 y = d.cross(x);
  struct Use {
    double angle;
    std::int32_t corner;
    bool forward;  // runs lo -> hi
  };
  std::vector<Use> around;
  for (const std::int32_t c : uses) {
    const Triangle& t = mesh.triangles[static_cast<std::size_t>(c / 3)];
    const int k = c % 3;
    const Vec3 w = mesh.vertices[static_cast<std::size_t>(t[(k + 2) % 3])] - a;  // the opposite corner
    around.push_back({std::atan2(w.dot(y), w.dot(x)), c, t[k] == lo});
  }
  std::sort(around.begin(), around.end(), [](const Use& p, const Use& q) { return p.angle < q.angle; });
  const std::size_t n = around.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Use& here = around[i];
    const Use& below = around[(i + n - 1) % n];  // the next half-plane towards decreasing angle
    if (here.angle == below.angle || here.forward == below.forward) return false;
    if (!here.forward) continue;
    twin[static_cast<std::size_t>(here.corner)] = below.corner;
    twin[static_cast<std::size_t>(below.corner)] = here.corner;
  }
  return true;
}

/// The twin of every halfedge (see pair_around_edge), or an empty vector when some edge has none.
/// The halfedges are grouped by undirected edge without a hash map: bucketed by their lower vertex
/// (a counting sort, which keeps them in corner order), then each small bucket sorted by the upper
/// vertex. Linear in the corners on a mesh of bounded degree.
std::vector<std::int32_t> twins(const Mesh& mesh, int& split_edges) {
  const auto corners = static_cast<std::int32_t>(3 * mesh.triangles.size());
  const auto ends = [&](std::int32_t c) {
    const Triangle& t = mesh.triangles[static_cast<std::size_t>(c / 3)];
    const std::int32_t p = t[c % 3], q = t[(c % 3 + 1) % 3];
    return std::pair{std::min(p, q), std::max(p, q)};
  };
  std::vector<std::int32_t> start(mesh.vertices.size() + 1, 0);
  for (std::int32_t c = 0; c < corners; ++c) ++start[static_cast<std::size_t>(ends(c).first) + 1];
  for (std::size_t v = 0; v + 1 < start.size(); ++v) start[v + 1] += start[v];
  std::vector<std::pair<std::int32_t, std::int32_t>> bucketed(static_cast<std::size_t>(corners));  // (upper, corner)
  {
    std::vector<std::int32_t> fill(start.begin(), start.end() - 1);
    for (std::int32_t c = 0; c < corners; ++c) {
      const auto [lo, hi] = ends(c);
      bucketed[static_cast<std::size_t>(fill[static_cast<std::size_t>(lo)]++)] = {hi, c};
    }
  }
  std::vector<std::int32_t> twin(static_cast<std::size_t>(corners), -1);
  std::vector<std::int32_t> halfedges;
  split_edges = 0;
  for (std::size_t lo = 0; lo + 1 < start.size(); ++lo) {
    const auto first = bucketed.begin() + start[lo], last = bucketed.begin() + start[lo + 1];
    std::sort(first, last);  // by upper vertex, then corner
    for (auto run = first; run != last;) {
      auto end = run;
      halfedges.clear();
      while (end != last && end->first == run->first) halfedges.push_back((end++)->second);
      const std::int32_t hi = run->first;
      run = end;
      if (halfedges.size() == 2) {
        const auto a = static_cast<std::size_t>(halfedges[0]), b = static_cast<std::size_t>(halfedges[1]);
        if (mesh.triangles[a / 3][a % 3] == mesh.triangles[b / 3][b % 3]) return {};
        twin[a] = halfedges[1];
        twin[b] = halfedges[0];
        continue;
      }
      if (halfedges.size() % 2 != 0 || !pair_around_edge(mesh, static_cast<std::int32_t>(lo), hi, halfedges, twin))
        return {};
      ++split_edges;
    }
  }
  return twin;
}

}  // namespace

PinchSplit split_pinched_vertices(Mesh& mesh) {
  // Corner c = 3 t + k is vertex triangles[t][k] and starts halfedge triangles[t][k] -> triangles[t][k + 1].
  // The corners around a vertex belong to one fan when they are linked through the edges leaving that
  // vertex: corner (t, k) of v, whose triangle holds prev -> v, and the corner of v in the triangle
  // holding that halfedge's twin v -> prev.
  PinchSplit split;
  const std::vector<std::int32_t> twin = twins(mesh, split.split_edges);
  if (twin.empty()) return {};
  const auto corners = static_cast<std::int32_t>(3 * mesh.triangles.size());
  std::vector<std::int32_t> parent(static_cast<std::size_t>(corners));
  std::iota(parent.begin(), parent.end(), 0);
  for (std::int32_t c = 0; c < corners; ++c) {
    const std::int32_t into = 3 * (c / 3) + (c % 3 + 2) % 3;  // halfedge prev -> v
    const std::int32_t a = find(parent, c);
    const std::int32_t b = find(parent, twin[static_cast<std::size_t>(into)]);
    if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }

  // The first fan seen keeps the vertex; every further fan gets a copy.
  std::vector<std::int32_t> fan_of_vertex(mesh.vertices.size(), -1);
  std::unordered_map<std::int32_t, std::int32_t> copy_of_fan;
  for (std::int32_t c = 0; c < corners; ++c) {
    std::int32_t& v = mesh.triangles[static_cast<std::size_t>(c / 3)][c % 3];
    const std::int32_t fan = find(parent, c);
    std::int32_t& owner = fan_of_vertex[static_cast<std::size_t>(v)];
    if (owner < 0) owner = fan;
    if (owner == fan) continue;
    const auto [it, inserted] = copy_of_fan.try_emplace(fan, -1);
    if (inserted) {
      it->second = mesh.add_vertex(Vec3(mesh.vertices[static_cast<std::size_t>(v)]));
      ++split.added_vertices;
    }
    v = it->second;
  }
  return split;
}

}  // namespace shatter
