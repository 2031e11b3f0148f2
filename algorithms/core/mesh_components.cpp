#include "algorithms/core/mesh_components.h"

#include "algorithms/core/attribute_transfer.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace shatter {
namespace {

/// Union-find over vertex indices with path halving.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::int32_t find(std::int32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void unite(std::int32_t a, std::int32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

  /// Number of sets (each vertex is in one; an unused vertex is a set of its own).
  [[nodiscard]] std::size_t count() const {
    std::size_t roots = 0;
    for (std::size_t v = 0; v < parent_.size(); ++v) roots += parent_[v] == static_cast<std::int32_t>(v);
    return roots;
  }

 private:
  std::vector<std::int32_t> parent_;
};

/// The vertices of each triangle joined: the sets are the mesh's parts (and its unused vertices).
DisjointSets vertex_sets(const Mesh& mesh) {
  DisjointSets sets(mesh.vertices.size());
  for (const Triangle& t : mesh.triangles) {
    sets.unite(t[0], t[1]);
    sets.unite(t[0], t[2]);
  }
  return sets;
}

/// Labels every vertex with its part (0..parts-1, numbered by first triangle) and returns the count;
/// unused vertices get -1.
int label_parts(const Mesh& mesh, DisjointSets& sets, std::vector<std::int32_t>& vertex_part) {
  std::vector<std::int32_t> root_part(mesh.vertices.size(), -1);
  vertex_part.assign(mesh.vertices.size(), -1);
  int parts = 0;
  for (const Triangle& t : mesh.triangles) {
    const std::int32_t root = sets.find(t[0]);
    if (root_part[root] < 0) root_part[root] = parts++;
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const std::int32_t root = sets.find(static_cast<std::int32_t>(v));
    vertex_part[v] = root_part[root];
  }
  return parts;
}

std::vector<Mesh> split_parts(const Mesh& mesh, const std::vector<std::int32_t>& vertex_part, int parts) {
  std::vector<Mesh> out(static_cast<std::size_t>(parts));
  for (Mesh& part : out) copy_attribute_frame(mesh, part);
  std::vector<std::int32_t> new_index(mesh.vertices.size(), -1);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    Mesh& part = out[static_cast<std::size_t>(vertex_part[t[0]])];
    Triangle mapped{};
    for (int k = 0; k < 3; ++k) {
      std::int32_t& idx = new_index[t[k]];
      if (idx < 0) idx = part.add_vertex(mesh.vertices[t[k]]);
      mapped[k] = idx;
    }
    add_triangle_from(part, mesh, f, mapped[0], mapped[1], mapped[2]);
  }
  return out;
}

}  // namespace

std::vector<Mesh> connected_components(const Mesh& mesh) {
  DisjointSets sets = vertex_sets(mesh);
  std::vector<std::int32_t> vertex_part;
  const int parts = label_parts(mesh, sets, vertex_part);
  return split_parts(mesh, vertex_part, parts);
}

std::vector<Mesh> connected_components(Mesh&& mesh) {
  DisjointSets sets = vertex_sets(mesh);
  // One set with a triangle: one part that uses every vertex (an unused vertex would be a set of its
  // own), the mesh as it is; no labels needed.
  if (!mesh.triangles.empty() && sets.count() == 1) {
    std::vector<Mesh> out;
    out.push_back(std::move(mesh));
    return out;
  }
  std::vector<std::int32_t> vertex_part;
  const int parts = label_parts(mesh, sets, vertex_part);
  return split_parts(mesh, vertex_part, parts);
}

}  // namespace shatter
