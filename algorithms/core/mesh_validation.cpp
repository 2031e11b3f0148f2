#include "algorithms/core/mesh_validation.h"

#include "algorithms/core/attribute_transfer.h"

#include "algorithms/core/edge_classification.h"
#include "algorithms/core/pinched_vertices.h"
#include "algorithms/core/shell_classification.h"
#include "algorithms/core/solid_check.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <vector>

namespace shatter {
namespace {

std::uint64_t mix(std::uint64_t z) {  // SplitMix64 finaliser
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

std::size_t table_size_for(std::size_t n) { return std::bit_ceil(std::max<std::size_t>(16, 2 * n)); }

/// For each vertex, the index of the first vertex with exactly the same coordinates (itself if none).
std::vector<std::int32_t> first_duplicates(const std::vector<Vec3>& vertices) {
  const std::size_t mask = table_size_for(vertices.size()) - 1;
  std::vector<std::int32_t> table(mask + 1, -1);
  std::vector<std::int32_t> representative(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    const Vec3& p = vertices[v];
    std::uint64_t h = 0;
    for (int i = 0; i < 3; ++i) h = mix(h ^ std::bit_cast<std::uint64_t>(p[i] + 0.0));  // -0 hashes as +0
    std::size_t slot = h & mask;
    while (table[slot] >= 0 && vertices[table[slot]] != p) slot = (slot + 1) & mask;
    if (table[slot] < 0) table[slot] = static_cast<std::int32_t>(v);
    representative[v] = table[slot];
  }
  return representative;
}

}  // namespace

Result<ValidationReport> validate_solid(Mesh& mesh, const std::string& what) {
  assert(mesh.tags.size() == mesh.triangles.size());
  auto fail = [&](const std::string& message) { return Error{what + ": " + message}; };
  if (mesh.triangles.empty() || mesh.vertices.empty()) return fail("empty mesh (no triangles)");
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!mesh.vertices[v].allFinite()) {
      std::ostringstream s;
      s << "vertex " << v << " has a non-finite coordinate (" << mesh.vertices[v].x() << ", "
        << mesh.vertices[v].y() << ", " << mesh.vertices[v].z() << ")";
      return fail(s.str());
    }
  const auto vertex_count = static_cast<std::int64_t>(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (const std::int32_t index : mesh.triangles[f])
      if (index < 0 || index >= vertex_count)
        return fail("triangle " + std::to_string(f) + " has vertex index " + std::to_string(index) +
                    " out of range (" + std::to_string(vertex_count) + " vertices)");

  // Merge exact duplicates, then keep the used vertices in their original order.
  ValidationReport report;
  const std::vector<std::int32_t> representative = first_duplicates(mesh.vertices);
  std::vector<char> used(mesh.vertices.size(), 0);
  for (Triangle& t : mesh.triangles)
    for (std::int32_t& index : t) used[index = representative[index]] = 1;
  std::vector<std::int32_t> new_index(mesh.vertices.size(), -1);
  std::vector<Vec3> kept;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (representative[v] != static_cast<std::int32_t>(v)) {
      ++report.merged_duplicate_vertices;
    } else if (!used[v]) {
      ++report.removed_unused_vertices;
    } else {
      new_index[v] = static_cast<std::int32_t>(kept.size());
      kept.push_back(mesh.vertices[v]);
    }
  }
  mesh.vertices = std::move(kept);
  for (Triangle& t : mesh.triangles)
    for (std::int32_t& index : t) index = new_index[index];

  // Sheets meeting at one vertex or along one edge (often made so by merging coincident vertices)
  // get vertices of their own; then a mesh that is a solid read inside out is turned outward.
  const PinchSplit split = split_pinched_vertices(mesh);
  report.split_pinched_vertices = split.added_vertices;
  report.split_non_manifold_edges = split.split_edges;
  if (is_closed_and_oriented(mesh)) {
    const ShellClassification shells = classify_shells(mesh);
    report.shells = static_cast<int>(shells.shells.size());
    // A cavity faces inward once the mesh faces outward (after the flip below, when inverted).
    report.cavities = static_cast<int>(std::count_if(shells.shells.begin(), shells.shells.end(),
                                                     [&](const Shell& s) { return s.outward() == shells.inverted; }));
    if (shells.inverted) {
      for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
      reverse_corner_order(mesh);
      report.flipped = true;
    }
  }
  // One rule for every solid (solid_check.h).
  if (Status s = check_solid(mesh, what, nullptr); !s) return s.error();
  return report;
}

bool is_closed_and_oriented(const Mesh& mesh) {
  const auto vertex_count = static_cast<std::int64_t>(mesh.vertices.size());
  for (const Triangle& t : mesh.triangles)
    for (const std::int32_t index : t)
      if (index < 0 || index >= vertex_count) return false;
  for (const Triangle& t : mesh.triangles)
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return false;
  // Closed and consistently oriented: every directed edge a->b is used exactly once, and so is b->a.
  // The half-edges are bucketed by their origin (a counting sort), and each a->b is counted in a's
  // bucket and its twin in b's: a plain scan of the few targets of an ordinary vertex, a binary search
  // in the sorted bucket of a vertex of many. Linear in the triangles, with no edge classification
  // arrays (this runs on every fragment of every fracture, fracture_output_check.h).
  constexpr std::int32_t kScanned = 32;  // buckets up to this size are scanned, larger ones sorted
  const std::size_t n = mesh.vertices.size();
  std::vector<std::int32_t> start(n + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (const std::int32_t a : t) ++start[static_cast<std::size_t>(a) + 1];
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<std::int32_t> target(3 * mesh.triangles.size());
  std::vector<std::int32_t> fill(start.begin(), start.end() - 1);
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) target[static_cast<std::size_t>(fill[static_cast<std::size_t>(t[i])]++)] = t[(i + 1) % 3];
  for (std::size_t v = 0; v < n; ++v)
    if (start[v + 1] - start[v] > kScanned) std::sort(target.begin() + start[v], target.begin() + start[v + 1]);
  // How often `x` is a target in the bucket of `v`.
  const auto uses = [&](std::size_t v, std::int32_t x) {
    const std::int32_t* first = target.data() + start[v];
    const std::int32_t* last = target.data() + start[v + 1];
    if (last - first > kScanned) {
      const auto range = std::equal_range(first, last, x);
      return static_cast<std::int32_t>(range.second - range.first);
    }
    std::int32_t count = 0;
    for (const std::int32_t* p = first; p != last; ++p) count += *p == x ? 1 : 0;
    return count;
  };
  bool ok = true;
  for (std::size_t a = 0; a < n && ok; ++a)
    for (std::int32_t k = start[a]; k < start[a + 1]; ++k) {
      const std::int32_t b = target[static_cast<std::size_t>(k)];
      ok &= uses(a, b) == 1 && uses(static_cast<std::size_t>(b), static_cast<std::int32_t>(a)) == 1;
    }
  return ok;
}

bool all_finite(const Mesh& mesh) {
  return std::all_of(mesh.vertices.begin(), mesh.vertices.end(), [](const Vec3& p) { return p.allFinite(); });
}

}  // namespace shatter
