#include "algorithms/repair/hausdorff_distance.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace shatter::repair {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle3 = Kernel::Triangle_3;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle3>::const_iterator>>>;

/// A soup's points and its triangles with area (zero-area triangles cannot be sampled).
struct Soup {
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> faces;
  std::vector<Triangle3> triangles;
};

Soup soup_of(const Mesh& mesh) {
  Soup soup;
  soup.points.reserve(mesh.vertices.size());
  for (const Vec3& p : mesh.vertices) soup.points.emplace_back(p.x(), p.y(), p.z());
  for (const shatter::Triangle& t : mesh.triangles) {
    const std::array<std::size_t, 3> f = {static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
                                          static_cast<std::size_t>(t[2])};
    if (CGAL::collinear(soup.points[f[0]], soup.points[f[1]], soup.points[f[2]])) continue;
    soup.faces.push_back(f);
    soup.triangles.emplace_back(soup.points[f[0]], soup.points[f[1]], soup.points[f[2]]);
  }
  return soup;
}

/// Largest distance from samples of `from` to the triangles of `to`.
double one_sided(const Soup& from, const Tree& to, const HausdorffSampling& sampling) {
  const auto count = static_cast<std::size_t>(
      std::max<double>(sampling.min_points, sampling.points_per_face * static_cast<double>(from.faces.size())));
  std::vector<Point> samples;
  PMP::sample_triangle_soup(from.points, from.faces, std::back_inserter(samples),
                            PMP::parameters::use_random_uniform_sampling(true)
                                .number_of_points_on_faces(count)
                                .do_sample_vertices(true)
                                .do_sample_edges(false)
                                .random_seed(0));
  double largest = 0.0;
  for (const Point& p : samples) largest = std::max(largest, CGAL::to_double(to.squared_distance(p)));
  return std::sqrt(largest);
}

}  // namespace

double hausdorff_distance(const Mesh& a, const Mesh& b, const HausdorffSampling& sampling) {
  const Soup soup_a = soup_of(a);
  const Soup soup_b = soup_of(b);
  if (soup_a.triangles.empty() || soup_b.triangles.empty()) return 0.0;
  Tree tree_a(soup_a.triangles.begin(), soup_a.triangles.end());
  Tree tree_b(soup_b.triangles.begin(), soup_b.triangles.end());
  tree_a.accelerate_distance_queries();
  tree_b.accelerate_distance_queries();
  return std::max(one_sided(soup_a, tree_b, sampling), one_sided(soup_b, tree_a, sampling));
}

}  // namespace shatter::repair
