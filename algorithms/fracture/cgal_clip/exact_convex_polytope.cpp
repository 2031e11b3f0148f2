#include "algorithms/fracture/cgal_clip/exact_convex_polytope.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace shatter::cgal_exact {
namespace {

/// Key of the directed edge a -> b.
std::uint64_t edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

/// The point where three planes meet (throws when they do not meet in one point).
ExactPoint corner(const ExactPlane& a, const ExactPlane& b, const ExactPlane& c) {
  const auto meet = CGAL::intersection(a, b, c);
  if (meet)
    if (const ExactPoint* p = boost::get<ExactPoint>(&*meet)) return *p;
  throw ClipFailure("three planes of a cell do not meet in one point");
}

}  // namespace

ExactConvexPolytope::ExactConvexPolytope(const Vec3& lower, const Vec3& upper) {
  // Vertex i has the upper x when bit 0 is set, the upper y for bit 1, the upper z for bit 2.
  for (int i = 0; i < 8; ++i)
    points_.emplace_back((i & 1) ? upper.x() : lower.x(), (i & 2) ? upper.y() : lower.y(),
                         (i & 4) ? upper.z() : lower.z());
  const std::array<std::array<int, 4>, 6> quads{{
      {0, 4, 6, 2}, {1, 3, 7, 5},  // x = lower, x = upper
      {0, 1, 5, 4}, {2, 6, 7, 3},  // y = lower, y = upper
      {0, 2, 3, 1}, {4, 5, 7, 6},  // z = lower, z = upper
  }};
  for (int axis = 0; axis < 3; ++axis) {
    for (int high = 0; high < 2; ++high) {
      Vec3 normal = Vec3::Zero();
      normal[axis] = high ? 1.0 : -1.0;
      planes_.push_back(exact_plane(high ? upper : lower, normal));
      sources_.push_back(-1);
      const auto& q = quads[2 * axis + high];
      faces_.push_back({static_cast<int>(planes_.size()) - 1, {q.begin(), q.end()}});
    }
  }
}

void ExactConvexPolytope::clip(const ExactPlane& plane, int source) {
  if (empty()) return;
  std::vector<CGAL::Oriented_side> side(points_.size());
  bool below = false;
  bool above = false;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    side[i] = plane.oriented_side(points_[i]);
    below = below || side[i] == CGAL::ON_NEGATIVE_SIDE;
    above = above || side[i] == CGAL::ON_POSITIVE_SIDE;
  }
  if (!below) {  // nothing strictly inside: at most a face, an edge or a vertex is left
    faces_.clear();
    points_.clear();
    return;
  }
  if (!above) return;  // the plane does not cut the polytope
  const int cut = static_cast<int>(planes_.size());
  planes_.push_back(plane);
  sources_.push_back(source);

  std::unordered_map<std::uint64_t, int> owner;  // directed edge -> face
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const std::vector<int>& c = faces_[f].corners;
    for (std::size_t k = 0; k < c.size(); ++k) owner.emplace(edge_key(c[k], c[(k + 1) % c.size()]), static_cast<int>(f));
  }

  // Each face clipped in turn (Sutherland-Hodgman); a crossing point is made once per edge, from the
  // planes of the two faces on the edge and the cut plane, and shared by both faces.
  std::unordered_map<std::uint64_t, int> crossing;
  std::vector<Face> kept;
  for (const Face& face : faces_) {
    Face out{face.plane, {}};
    bool has_below = false;
    const std::vector<int>& c = face.corners;
    for (std::size_t k = 0; k < c.size(); ++k) {
      const int a = c[k];
      const int b = c[(k + 1) % c.size()];
      if (side[a] != CGAL::ON_POSITIVE_SIDE) {
        out.corners.push_back(a);
        has_below = has_below || side[a] == CGAL::ON_NEGATIVE_SIDE;
      }
      if (side[a] == CGAL::ON_ORIENTED_BOUNDARY || side[b] == CGAL::ON_ORIENTED_BOUNDARY || side[a] == side[b])
        continue;
      const auto [it, made] = crossing.try_emplace(edge_key(std::min(a, b), std::max(a, b)), static_cast<int>(points_.size()));
      if (made) {
        const auto twin = owner.find(edge_key(b, a));
        if (twin == owner.end()) throw ClipFailure("a cell polytope is not closed");
        points_.push_back(corner(planes_[face.plane], planes_[faces_[twin->second].plane], plane));
      }
      out.corners.push_back(it->second);
    }
    // A face with no corner strictly below keeps at most an edge in the plane: dropped.
    if (has_below) kept.push_back(std::move(out));
  }

  // The cap: the kept faces' edges that lost their twin, reversed and chained, from the smallest index.
  std::unordered_set<std::uint64_t> edges;
  for (const Face& face : kept)
    for (std::size_t k = 0; k < face.corners.size(); ++k)
      edges.insert(edge_key(face.corners[k], face.corners[(k + 1) % face.corners.size()]));
  std::unordered_map<int, int> next;
  int start = std::numeric_limits<int>::max();
  for (const Face& face : kept) {
    for (std::size_t k = 0; k < face.corners.size(); ++k) {
      const int a = face.corners[k];
      const int b = face.corners[(k + 1) % face.corners.size()];
      if (edges.count(edge_key(b, a))) continue;
      if (!next.emplace(b, a).second) throw ClipFailure("the cap of a cell polytope is not one loop");
      start = std::min(start, b);
    }
  }
  Face cap{cut, {}};
  for (int v = start; next.size() >= 3 && cap.corners.size() <= next.size();) {
    cap.corners.push_back(v);
    const auto it = next.find(v);
    if (it == next.end()) break;
    v = it->second;
    if (v == start) break;
  }
  if (next.size() < 3 || cap.corners.size() != next.size())
    throw ClipFailure("the cap of a cell polytope is not one loop");
  kept.push_back(std::move(cap));

  // Drop the vertices left above, keeping the order of the others.
  std::vector<int> index(points_.size(), -1);
  for (const Face& face : kept)
    for (int v : face.corners) index[v] = 0;
  std::vector<ExactPoint> points;
  for (std::size_t v = 0; v < points_.size(); ++v) {
    if (index[v] < 0) continue;
    index[v] = static_cast<int>(points.size());
    points.push_back(points_[v]);
  }
  for (Face& face : kept)
    for (int& v : face.corners) v = index[v];
  points_ = std::move(points);
  faces_ = std::move(kept);
}

std::array<Vec3, 2> ExactConvexPolytope::bounds() const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::array<Vec3, 2> box{Vec3::Constant(inf), Vec3::Constant(-inf)};
  for (const ExactPoint& p : points_) {
    const auto& a = p.approx();
    box[0] = box[0].cwiseMin(Vec3(a.x().inf(), a.y().inf(), a.z().inf()));
    box[1] = box[1].cwiseMax(Vec3(a.x().sup(), a.y().sup(), a.z().sup()));
  }
  return box;
}

std::vector<int> ExactConvexPolytope::face_sources() const {
  std::vector<int> out;
  out.reserve(faces_.size());
  for (const Face& face : faces_) out.push_back(sources_[face.plane]);
  return out;
}

SurfaceMesh ExactConvexPolytope::triangle_mesh() const {
  SurfaceMesh mesh;
  std::vector<VertexIndex> index;
  index.reserve(points_.size());
  for (const ExactPoint& p : points_) index.push_back(mesh.add_vertex(p));
  for (const Face& face : faces_) {
    const std::vector<int>& c = face.corners;
    for (std::size_t k = 1; k + 1 < c.size(); ++k)
      if (mesh.add_face(index[c[0]], index[c[k]], index[c[k + 1]]) == SurfaceMesh::null_face())
        throw ClipFailure("a cell polytope is not 2-manifold");
  }
  return mesh;
}

}  // namespace shatter::cgal_exact
