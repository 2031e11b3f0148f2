#include "harness/cases/prism_mesh.h"

#include "algorithms/core/cap_triangulator.h"
#include "harness/cases/physical_range.h"
#include "harness/limits.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace shatter {
namespace {

using json = nlohmann::json;

/// Reads an array of >= 3 [x, z] pairs.
bool read_polygon(JsonReader& r, const json& value, const std::string& path, std::vector<Vec2>& out) {
  if (!r.array(value, path)) return false;
  if (value.size() < 3) {
    r.fail(path, fmt::format("a polygon needs at least 3 corners, got {}", value.size()));
    return false;
  }
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string at = fmt::format("{}[{}]", path, i);
    const json& corner = value[i];
    if (!corner.is_array() || corner.size() != 2) {
      r.fail(at, "expected [x, z]");
      return false;
    }
    Vec2 p;
    if (!r.convert(corner[0], at, p.x()) || !r.convert(corner[1], at, p.y())) return false;
    if (!check_in_range(r, at + "[0]", p.x(), kCoordinateRange) || !check_in_range(r, at + "[1]", p.y(), kCoordinateRange))
      return false;
    out.push_back(p);
  }
  return true;
}

double signed_area(const std::vector<Vec2>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

}  // namespace

PrismSpec read_prism(JsonReader& r, const json& v, std::string_view path) {
  PrismSpec s;
  if (!r.object(v, path, {"outline", "holes", "depth", "y"})) return s;
  const std::string outline_at = fmt::format("{}.outline", path);
  if (!v.contains("outline")) {
    r.fail(outline_at, "missing required key");
    return s;
  }
  if (!read_polygon(r, v.at("outline"), outline_at, s.outline)) return s;
  std::size_t corners = s.outline.size();
  if (v.contains("holes")) {
    const std::string holes_at = fmt::format("{}.holes", path);
    if (!r.array(v.at("holes"), holes_at)) return s;
    for (std::size_t i = 0; i < v.at("holes").size(); ++i) {
      s.holes.emplace_back();
      if (!read_polygon(r, v.at("holes")[i], fmt::format("{}[{}]", holes_at, i), s.holes.back())) return s;
      corners += s.holes.back().size();
    }
  }
  if (corners > static_cast<std::size_t>(kMaxPrismCorners)) {
    r.fail(path, fmt::format("{} corners (outline and holes) exceed the limit of {} corners per prism", corners,
                             kMaxPrismCorners));
    return s;
  }
  read_in_range(r, v, path, "depth", s.depth, kLengthRange);
  read_in_range(r, v, path, "y", s.y, kCoordinateRange);
  return s;
}

Result<Mesh> make_prism(const PrismSpec& spec, const std::string& what) {
  // The region lies left of its edges: outline counter-clockwise, holes clockwise, whatever was given.
  std::vector<Vec2> points;
  std::vector<CapEdge> edges;
  const auto add_loop = [&](std::vector<Vec2> loop, bool outer) {
    if ((signed_area(loop) > 0) != outer) std::reverse(loop.begin(), loop.end());
    const auto first = static_cast<std::int32_t>(points.size());
    const auto n = static_cast<std::int32_t>(loop.size());
    for (std::int32_t i = 0; i < n; ++i) {
      points.push_back(loop[static_cast<std::size_t>(i)]);
      edges.push_back({first + i, first + (i + 1) % n});
    }
  };
  add_loop(spec.outline, true);
  for (const auto& hole : spec.holes) add_loop(hole, false);

  const CapTriangulation profile = triangulate_cap(points, edges);
  if (!profile.ok) return Error{what + ": prism: the outline or a hole crosses itself or another (" + profile.error + ")"};
  double area = 0.0;
  for (const Triangle& t : profile.triangles) {
    const Vec2 &a = points[static_cast<std::size_t>(t[0])], &b = points[static_cast<std::size_t>(t[1])],
               &c = points[static_cast<std::size_t>(t[2])];
    area += 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  }
  if (!(area > 0.0)) return Error{what + ": prism: the profile has no area"};

  // Vertices: front copies 0..n-1 at y - depth/2, back copies n..2n-1 at y + depth/2.
  Mesh mesh;
  const auto n = static_cast<std::int32_t>(points.size());
  const double front = spec.y - 0.5 * spec.depth;
  const double back = spec.y + 0.5 * spec.depth;
  for (const Vec2& p : points) mesh.add_vertex({p.x(), front, p.y()});
  for (const Vec2& p : points) mesh.add_vertex({p.x(), back, p.y()});
  // Counter-clockwise in (x, z) faces -y: as is on the front, reversed on the back.
  for (const Triangle& t : profile.triangles) {
    mesh.add_triangle(t[0], t[1], t[2], FaceTag::surface);
    mesh.add_triangle(t[0] + n, t[2] + n, t[1] + n, FaceTag::surface);
  }
  // One quad per edge; the region is left of a -> b, so the outward side is to its right.
  for (const CapEdge& e : edges) {
    const std::int32_t a = e[0], b = e[1];
    mesh.add_triangle(a, b + n, b, FaceTag::surface);
    mesh.add_triangle(a, a + n, b + n, FaceTag::surface);
  }
  return mesh;
}

}  // namespace shatter
