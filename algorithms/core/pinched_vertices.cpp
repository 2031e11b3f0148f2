#include "algorithms/core/pinched_vertices.h"

#include <cassert>
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace shatter {
namespace {

std::uint64_t key(std::int32_t a, std::int32_t b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

std::int32_t find(std::vector<std::int32_t>& parent, std::int32_t x) {
  while (parent[static_cast<std::size_t>(x)] != x) {
    parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    x = parent[static_cast<std::size_t>(x)];
  }
  return x;
}

}  // namespace

int split_pinched_vertices(Mesh& mesh) {
  // Corner c = 3 t + k is vertex triangles[t][k]. The corners around a vertex belong to one fan when
  // they are linked through the edges leaving that vertex: corner (t, k) with edge v -> a, and the
  // corner of v in the triangle holding the twin a -> v.
  const auto corners = static_cast<std::int32_t>(3 * mesh.triangles.size());
  std::unordered_map<std::uint64_t, std::int32_t> corner_of_halfedge;  // (v -> a) -> corner of v
  corner_of_halfedge.reserve(static_cast<std::size_t>(corners));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      corner_of_halfedge.emplace(key(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]),
                                 static_cast<std::int32_t>(3 * t + k));

  std::vector<std::int32_t> parent(static_cast<std::size_t>(corners));
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t v = mesh.triangles[t][k];
      const std::int32_t prev = mesh.triangles[t][(k + 2) % 3];
      // The triangle across edge prev -> v holds v -> prev; its corner of v joins this fan.
      const auto twin = corner_of_halfedge.find(key(v, prev));
      assert(twin != corner_of_halfedge.end() && "split_pinched_vertices needs a closed mesh");
      if (twin == corner_of_halfedge.end()) continue;
      const std::int32_t a = find(parent, static_cast<std::int32_t>(3 * t + k));
      const std::int32_t b = find(parent, twin->second);
      if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    }
  }

  // The first fan seen keeps the vertex; every further fan gets a copy.
  std::vector<std::int32_t> fan_of_vertex(mesh.vertices.size(), -1);
  std::unordered_map<std::int32_t, std::int32_t> copy_of_fan;
  int added = 0;
  for (std::int32_t c = 0; c < corners; ++c) {
    std::int32_t& v = mesh.triangles[static_cast<std::size_t>(c / 3)][c % 3];
    const std::int32_t fan = find(parent, c);
    std::int32_t& owner = fan_of_vertex[static_cast<std::size_t>(v)];
    if (owner < 0) owner = fan;
    if (owner == fan) continue;
    const auto [it, inserted] = copy_of_fan.try_emplace(fan, -1);
    if (inserted) {
      it->second = mesh.add_vertex(Vec3(mesh.vertices[static_cast<std::size_t>(v)]));
      ++added;
    }
    v = it->second;
  }
  return added;
}

}  // namespace shatter
