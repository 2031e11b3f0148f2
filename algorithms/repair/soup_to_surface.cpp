#include "algorithms/repair/soup_to_surface.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace shatter::repair {
namespace {

using Polygon = std::vector<std::size_t>;
/// A triangle's corner positions in lexicographic order: the same key for every orientation.
using CornerKey = std::array<double, 9>;

CornerKey corner_key(const Point& a, const Point& b, const Point& c) {
  std::array<std::array<double, 3>, 3> corners = {{{a.x(), a.y(), a.z()}, {b.x(), b.y(), b.z()}, {c.x(), c.y(), c.z()}}};
  std::sort(corners.begin(), corners.end());
  CornerKey key{};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) key[static_cast<std::size_t>(3 * i + k)] = corners[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
  return key;
}

}  // namespace

SoupSurface soup_to_surface(const Mesh& soup) {
  SoupSurface out;
  std::vector<Point> points;
  points.reserve(soup.vertices.size());
  for (const Vec3& p : soup.vertices) points.emplace_back(p.x(), p.y(), p.z());

  // Origins by corner positions: cleaning reorders and drops polygons, positions stay.
  std::map<CornerKey, std::int32_t> origin_of;
  std::vector<Polygon> polygons;
  polygons.reserve(soup.triangles.size());
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const Triangle& tri = soup.triangles[t];
    polygons.push_back({static_cast<std::size_t>(tri[0]), static_cast<std::size_t>(tri[1]), static_cast<std::size_t>(tri[2])});
    origin_of.emplace(corner_key(points[polygons.back()[0]], points[polygons.back()[1]], points[polygons.back()[2]]),
                      static_cast<std::int32_t>(t));
  }
  // Vertices merged: referenced positions that another referenced vertex already holds.
  PMP::remove_isolated_points_in_polygon_soup(points, polygons);
  out.vertices_merged = static_cast<int>(PMP::merge_duplicate_points_in_polygon_soup(points, polygons));
  PMP::repair_polygon_soup(points, polygons);
  out.faces_removed = static_cast<int>(soup.triangles.size() - polygons.size());

  PMP::orient_polygon_soup(points, polygons);
  if (PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    PMP::polygon_soup_to_polygon_mesh(points, polygons, out.surface);
  } else {  // not expected after orient_polygon_soup; faces that do not fit are dropped
    for (const Point& p : points) out.surface.add_vertex(p);
    for (const Polygon& polygon : polygons)
      if (out.surface.add_face(SurfaceMesh::Vertex_index(static_cast<std::uint32_t>(polygon[0])),
                               SurfaceMesh::Vertex_index(static_cast<std::uint32_t>(polygon[1])),
                               SurfaceMesh::Vertex_index(static_cast<std::uint32_t>(polygon[2]))) == SurfaceMesh::null_face())
        ++out.faces_removed;
  }
  OriginMap origin = origin_map(out.surface);
  for (FaceIndex f : out.surface.faces()) {
    const auto h = out.surface.halfedge(f);
    const auto found = origin_of.find(corner_key(out.surface.point(out.surface.source(h)),
                                                 out.surface.point(out.surface.target(h)),
                                                 out.surface.point(out.surface.target(out.surface.next(h)))));
    origin[f] = found != origin_of.end() ? found->second : -1;
  }
  return out;
}

}  // namespace shatter::repair
