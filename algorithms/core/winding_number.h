#pragma once
/// Generalized winding number of a triangle mesh (Jacobson, Kavan, Sorkine-Hornung 2013): the sum of
/// the signed solid angles its triangles subtend at a query point, divided by 4 pi. For a closed,
/// outward-oriented mesh it is 1 inside, 0 outside and 1/2 on a face, up to round-off; an inward
/// mesh gives -1 inside; nested or overlapping shells add up. It is the inside test the fracture
/// metrics use, because it needs no ray and no tie-breaking at edges and vertices.
///
/// Convention on the surface: a triangle whose plane contains the query point contributes 0, so a
/// point on a flat face gets 1/2, on a convex box edge 1/4 and at a box corner 1/8 (the share of the
/// surrounding sphere that lies inside).

#include "algorithms/core/mesh.h"

#include <array>
#include <vector>

namespace shatter {

/// Signed solid angle (steradians, in (-2 pi, 2 pi)) of the triangle (a, b, c) seen from `q`, by the
/// Van Oosterom-Strackee formula; positive when q is behind the triangle (on the side opposite to
/// its normal, as a point inside an outward mesh is). 0 when q lies in the triangle's plane.
double triangle_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& q);

/// Generalized winding number of `mesh` at `q` (dimensionless): one pass over all #F triangles.
double winding_number(const Mesh& mesh, const Vec3& q);

/// Winding number of one closed mesh at many points, exact up to round-off and much faster than
/// winding_number() on large meshes.
///
/// Design note: the triangles are sorted into a bounding-volume tree. A subset of triangles with
/// boundary edges E, closed by a fan from one of its own vertices over E reversed, is a closed
/// surface inside the subset's box, so its winding number is exactly 0 outside that box: there the
/// subset contributes exactly what the fan over E (kept in E's direction) contributes (Jacobson et
/// al. 2013, section 3.3). A fan has O(sqrt(#triangles)) triangles on a surface-like subset, so a
/// query only visits the nodes whose box holds the point. This is an identity, not a far-field
/// approximation. Boundary edges are found on vertex indices, so the identity holds for any mesh;
/// only the shortcut at the root (0 outside the whole box) needs the mesh to be closed.
class WindingNumberQuery {
 public:
  /// Builds the tree over `mesh` (#F triangles; copies the positions, O(#F log #F)).
  explicit WindingNumberQuery(const Mesh& mesh);

  /// Winding number at `q`; exactly 0 when `q` is outside bounds().
  double operator()(const Vec3& q) const;

  /// Bounding box of the triangles' corners, m (empty for a mesh without triangles).
  [[nodiscard]] const Aabb& bounds() const { return bounds_; }

  /// Number of triangles of the mesh.
  [[nodiscard]] std::size_t triangle_count() const { return triangles_.size(); }

  /// True when the mesh's directed edges cancel (each a->b as often as b->a): it bounds, and its
  /// winding number off the surface is an integer. False for a mesh without triangles.
  [[nodiscard]] bool closed() const { return closed_; }

 private:
  // A tree node: triangles_[begin, end) and, for an inner node with a small enough boundary, the
  // boundary fan in fans_[fan_begin, fan_end) (fan_begin < 0: no fan, always descend).
  struct Node {
    Aabb box;
    int begin = 0, end = 0;
    int left = -1, right = -1;  // children, -1 for a leaf
    int fan_begin = -1, fan_end = -1;
  };
  // Directed edge with multiplicity, between vertex indices.
  struct Edge {
    std::int32_t from, to;
    int count;
  };

  // A triangle and the sum of its corners (3 x centroid), the key of the median split.
  struct Keyed {
    Vec3 sum;
    Triangle triangle;
  };

  void build(const Mesh& mesh, std::vector<Keyed>& order, int node, int begin, int end, std::vector<Edge>& edges);

  // Triangles as indices into the tree's own copy of the positions (12 bytes each, against 72 for
  // three corners: the fans of all levels together hold more triangles than the mesh).
  std::vector<Vec3> points_;         // the mesh's positions, m
  std::vector<Triangle> triangles_;  // #F triangles in tree order
  std::vector<Triangle> fans_;       // boundary fans of the inner nodes, edges in their own direction
  std::vector<Node> nodes_;         // nodes_[0] is the root
  Aabb bounds_;
  bool closed_ = false;
};

}  // namespace shatter
