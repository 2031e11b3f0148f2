#include "algorithms/core/mesh_validation.h"

#include "algorithms/core/pinched_vertices.h"
#include "algorithms/core/shell_classification.h"

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

/// How the undirected edge under one directed triangle edge is used.
enum class EdgeState : std::uint8_t { ok, open, non_manifold, misoriented };

/// Per directed edge 3 f + i (corner i to corner i + 1 of triangle f): the state of its undirected
/// edge and how many triangles use it.
struct EdgeClassification {
  std::vector<EdgeState> state;
  std::vector<std::int32_t> uses;
};

/// Buckets the directed edges by their lower vertex (counting sort, cache friendly) and sorts each
/// small bucket by the upper vertex, so that the uses of one undirected edge are adjacent.
EdgeClassification classify_edges(const std::vector<Triangle>& triangles, std::size_t vertex_count) {
  const std::size_t edge_count = 3 * triangles.size();
  std::vector<std::int32_t> lower(edge_count), upper(edge_count);
  std::vector<char> forward(edge_count);
  std::vector<std::int32_t> start(vertex_count + 1, 0);
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (int i = 0; i < 3; ++i) {
      const std::int32_t a = triangles[f][i], b = triangles[f][(i + 1) % 3];
      const std::size_t e = 3 * f + i;
      lower[e] = std::min(a, b);
      upper[e] = std::max(a, b);
      forward[e] = a < b;
      ++start[lower[e] + 1];
    }
  for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
  std::vector<std::int32_t> bucketed(edge_count), fill(start.begin(), start.end() - 1);
  for (std::size_t e = 0; e < edge_count; ++e) bucketed[fill[lower[e]]++] = static_cast<std::int32_t>(e);

  EdgeClassification result{std::vector<EdgeState>(edge_count), std::vector<std::int32_t>(edge_count)};
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const auto first = bucketed.begin() + start[v], last = bucketed.begin() + start[v + 1];
    std::sort(first, last, [&](std::int32_t x, std::int32_t y) { return upper[x] < upper[y] || (upper[x] == upper[y] && x < y); });
    for (auto run = first; run != last;) {
      auto end = run;
      int forwards = 0;
      while (end != last && upper[*end] == upper[*run]) forwards += forward[*end++];
      const auto uses = static_cast<std::int32_t>(end - run);
      const EdgeState state = uses < 2   ? EdgeState::open
                              : uses > 2 ? EdgeState::non_manifold
                              : forwards != 1 ? EdgeState::misoriented
                                              : EdgeState::ok;
      for (auto it = run; it != end; ++it) {
        result.state[*it] = state;
        result.uses[*it] = uses;
      }
      run = end;
    }
  }
  return result;
}

/// Shewchuk's two-sum and two-product: a + b and a * b as exact unevaluated sums hi + lo.
void two_sum(double a, double b, double& hi, double& lo) {
  hi = a + b;
  const double bv = hi - a;
  lo = (a - (hi - bv)) + (b - bv);
}

/// Adds `b` to the non-overlapping expansion `e` (Shewchuk's Grow-Expansion), keeping it exact.
void grow_expansion(std::vector<double>& e, double b) {
  double q = b;
  for (double& component : e) {
    double hi, lo;
    two_sum(q, component, hi, lo);
    component = lo;
    q = hi;
  }
  e.push_back(q);
}

/// Exact sign of ax*by - ay*bx + bx*cy - by*cx + cx*ay - cy*ax (orient2d, expanded so that no
/// rounded difference enters).
int exact_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double terms[6][2] = {{ax, by}, {-ay, bx}, {bx, cy}, {-by, cx}, {cx, ay}, {-cy, ax}};
  std::vector<double> e;
  e.reserve(13);
  for (const auto& t : terms) {
    const double p = t[0] * t[1];
    grow_expansion(e, p);
    grow_expansion(e, std::fma(t[0], t[1], -p));  // exact product error (barring underflow)
  }
  for (auto it = e.rbegin(); it != e.rend(); ++it)  // the largest non-zero component has the sign
    if (*it != 0.0) return *it > 0.0 ? 1 : -1;
  return 0;
}

/// True when a, b, c are exactly collinear: all three coordinate-plane projections have zero area.
bool exactly_collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, v = c - a;
  for (int axis = 0; axis < 3; ++axis) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    // Floating-point filter (Shewchuk's ccwerrboundA): a clearly non-zero projection decides.
    const double left = u[i] * v[j], right = u[j] * v[i];
    if (std::abs(left - right) > 3.3306690738754716e-16 * (std::abs(left) + std::abs(right))) return false;
  }
  for (int axis = 0; axis < 3; ++axis) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    if (exact_orient2d(a[i], a[j], b[i], b[j], c[i], c[j]) != 0) return false;
  }
  return true;
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
  std::vector<std::int32_t> new_index(mesh.vertices.size(), -1), original;
  std::vector<Vec3> kept;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (representative[v] != static_cast<std::int32_t>(v)) {
      ++report.merged_duplicate_vertices;
    } else if (!used[v]) {
      ++report.removed_unused_vertices;
    } else {
      new_index[v] = static_cast<std::int32_t>(kept.size());
      kept.push_back(mesh.vertices[v]);
      original.push_back(static_cast<std::int32_t>(v));
    }
  }
  mesh.vertices = std::move(kept);
  for (Triangle& t : mesh.triangles)
    for (std::int32_t& index : t) index = new_index[index];

  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      return fail("triangle " + std::to_string(f) + " is degenerate (repeated vertex)");
    if (exactly_collinear(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]))
      return fail("triangle " + std::to_string(f) + " has zero area (collinear corners)");
  }

  // Report the first bad edge in triangle order (with the input's vertex numbers), holes before
  // non-manifold edges before orientation.
  const EdgeClassification edges = classify_edges(mesh.triangles, mesh.vertices.size());
  for (const EdgeState wanted : {EdgeState::open, EdgeState::non_manifold, EdgeState::misoriented}) {
    const auto bad = std::find(edges.state.begin(), edges.state.end(), wanted);
    if (bad == edges.state.end()) continue;
    const auto e = static_cast<std::size_t>(bad - edges.state.begin());
    const Triangle& t = mesh.triangles[e / 3];
    const std::int32_t a = original[t[e % 3]], b = original[t[(e % 3 + 1) % 3]];
    const std::string edge = "edge (" + std::to_string(std::min(a, b)) + ", " + std::to_string(std::max(a, b)) + ")";
    if (wanted == EdgeState::open) return fail("not closed: " + edge + " is used by 1 triangle");
    if (wanted == EdgeState::non_manifold)
      return fail("not 2-manifold: " + edge + " is used by " + std::to_string(edges.uses[e]) + " triangles");
    return fail("inconsistent orientation at " + edge);
  }

  // Sheets meeting at a single vertex (often made so by merging coincident vertices) get a vertex each.
  report.split_pinched_vertices = split_pinched_vertices(mesh);

  // A closed shell whose volume rounds to nothing relative to the mesh's size is flat: reject it.
  const ShellClassification shells = classify_shells(mesh);
  const double size = bounding_box(mesh).diagonal();
  for (int s = 0; s < static_cast<int>(shells.shells.size()); ++s)
    if (std::abs(shells.shells[static_cast<std::size_t>(s)].volume) <= 1e-14 * size * size * size)
      return fail(shells.shells.size() == 1 ? "zero volume (flat closed mesh)"
                                            : "zero volume: " + shell_name(shells, s) + " is flat");
  // One rule for every solid: outward shells that neither cross nor nest (shell_classification.h).
  if (shells.verdict != SolidVerdict::solid) return fail(shells.reason);
  report.shells = static_cast<int>(shells.shells.size());
  if (shells.inverted) {
    for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
    report.flipped = true;
  }
  return report;
}

bool is_closed_and_oriented(const Mesh& mesh) {
  const auto vertex_count = static_cast<std::int64_t>(mesh.vertices.size());
  for (const Triangle& t : mesh.triangles)
    for (const std::int32_t index : t)
      if (index < 0 || index >= vertex_count) return false;
  for (const Triangle& t : mesh.triangles)
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return false;
  const EdgeClassification edges = classify_edges(mesh.triangles, mesh.vertices.size());
  return std::all_of(edges.state.begin(), edges.state.end(), [](EdgeState s) { return s == EdgeState::ok; });
}

bool all_finite(const Mesh& mesh) {
  return std::all_of(mesh.vertices.begin(), mesh.vertices.end(), [](const Vec3& p) { return p.allFinite(); });
}

}  // namespace shatter
