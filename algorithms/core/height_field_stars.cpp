#include "algorithms/core/height_field_stars.h"

#include "algorithms/core/axis_projection.h"
#include "algorithms/core/predicates.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <span>

namespace shatter {
namespace {

/// The edge of a vertex's link contributed by one triangle (v, from, to) of its star, with the
/// orientation of that triangle's projection along the vertex's axis.
struct LinkEdge {
  std::int32_t from;
  std::int32_t to;
  int orientation;
};

/// Direction from c to p lies in the half-plane [0, pi) of angles: y above c, or on c's line with x to
/// the right. Exact: compares coordinates only.
bool upper_half(const Vec2& c, const Vec2& p) { return p.y() > c.y() || (p.y() == c.y() && p.x() > c.x()); }

/// Relative round-off bounds fail where products fall into the subnormal range; below this bound a
/// filter leaves the decision to the exact predicate.
constexpr double kFilterFloor = 1e-280;

/// Sign of the orientation of triangle abc projected along `axis` (orient2d of the dropped
/// coordinates, any corner first): component `axis` of (b - a) x (c - a) when it is clear of its
/// round-off (Shewchuk's first bound, 3u + 16u^2 of the two products' magnitudes, taken as 1e-15),
/// else the exact predicate. The bound holds only away from underflow, hence the floor (kFilterFloor).
int projected_orientation(const Vec3& a, const Vec3& b, const Vec3& c, int axis) {
  const int i = (axis + 1) % 3;
  const int j = (axis + 2) % 3;
  const double left = (b[i] - a[i]) * (c[j] - a[j]);
  const double right = (b[j] - a[j]) * (c[i] - a[i]);
  const double det = left - right;
  const double bound = 1e-15 * (std::abs(left) + std::abs(right));
  if (bound >= kFilterFloor) {
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  return orient2d(drop_axis(a, axis), drop_axis(b, axis), drop_axis(c, axis));
}

/// Stamps per vertex for the permutation test, kept across vertices: `left[x] == stamp` when some
/// link edge of the current vertex leaves x, `entered[x] == stamp` when one enters it.
struct LinkMarks {
  std::vector<std::int32_t> left;
  std::vector<std::int32_t> entered;
};

/// The link edges form a permutation of the link vertices: each leaves a distinct vertex, enters a
/// distinct vertex, and enters only vertices that are left. O(d).
bool is_permutation_of_link(std::span<const LinkEdge> edges, std::int32_t stamp, LinkMarks& marks) {
  for (const LinkEdge& e : edges) {
    std::int32_t& mark = marks.left[static_cast<std::size_t>(e.from)];
    if (mark == stamp) return false;
    mark = stamp;
  }
  for (const LinkEdge& e : edges) {
    std::int32_t& mark = marks.entered[static_cast<std::size_t>(e.to)];
    if (mark == stamp || marks.left[static_cast<std::size_t>(e.to)] != stamp) return false;
    mark = stamp;
  }
  return true;
}

bool star_is_height_field(const Mesh& mesh, std::size_t v, int axis, std::span<const LinkEdge> edges,
                          LinkMarks& marks) {
  if (edges.size() < 3) return false;
  const int orientation = edges.front().orientation;
  if (orientation == 0) return false;
  for (const LinkEdge& e : edges)
    if (e.orientation != orientation) return false;
  if (!is_permutation_of_link(edges, static_cast<std::int32_t>(v), marks)) return false;
  const Vec2 c = drop_axis(mesh.vertices[v], axis);
  int windings = 0;
  for (const LinkEdge& e : edges) {
    // Counter-clockwise turns cross +x from the lower half to the upper, clockwise ones the other way.
    const bool a_up = upper_half(c, drop_axis(mesh.vertices[static_cast<std::size_t>(e.from)], axis));
    const bool b_up = upper_half(c, drop_axis(mesh.vertices[static_cast<std::size_t>(e.to)], axis));
    windings += orientation > 0 ? (!a_up && b_up) : (a_up && !b_up);
  }
  return windings == 1;
}

}  // namespace

std::vector<std::uint8_t> height_field_stars(const Mesh& mesh) {
  const std::size_t vertex_count = mesh.vertices.size();
  const auto at = [&mesh](std::int32_t v) -> const Vec3& { return mesh.vertices[static_cast<std::size_t>(v)]; };
  // Valences, and each vertex's axis: the largest component of its triangles' summed normals.
  std::vector<std::int32_t> start(vertex_count + 1, 0);
  std::vector<Vec3> normal_sum(vertex_count, Vec3::Zero());
  for (const Triangle& t : mesh.triangles) {
    const Vec3 n = (at(t[1]) - at(t[0])).cross(at(t[2]) - at(t[0]));
    for (const std::int32_t v : t) {
      ++start[static_cast<std::size_t>(v) + 1];
      normal_sum[static_cast<std::size_t>(v)] += n;
    }
  }
  std::vector<std::uint8_t> axis(vertex_count);
  for (std::size_t v = 0; v < vertex_count; ++v) {
    axis[v] = static_cast<std::uint8_t>(dominant_axis(normal_sum[v]));
    start[v + 1] += start[v];
  }
  std::vector<LinkEdge> links(static_cast<std::size_t>(start[vertex_count]));
  std::vector<std::int32_t> fill(start.begin(), start.end() - 1);
  for (const Triangle& t : mesh.triangles) {
    std::array<int, 3> orientation{2, 2, 2};  // per axis, 2 until needed
    for (int k = 0; k < 3; ++k) {
      const auto v = static_cast<std::size_t>(t[k]);
      int& o = orientation[axis[v]];
      if (o == 2) o = projected_orientation(at(t[0]), at(t[1]), at(t[2]), axis[v]);
      links[static_cast<std::size_t>(fill[v]++)] = {t[(k + 1) % 3], t[(k + 2) % 3], o};
    }
  }
  std::vector<std::uint8_t> height_field(vertex_count, 0);
  LinkMarks marks{std::vector<std::int32_t>(vertex_count, -1), std::vector<std::int32_t>(vertex_count, -1)};
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const std::span<const LinkEdge> edges(links.data() + start[v], links.data() + start[v + 1]);
    height_field[v] = star_is_height_field(mesh, v, axis[v], edges, marks) ? 1 : 0;
  }
  return height_field;
}

}  // namespace shatter
