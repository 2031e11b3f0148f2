#include "algorithms/bonds/support_graph.h"

#include "algorithms/bonds/section_moments.h"
#include "algorithms/core/mass_properties.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

namespace shatter {

namespace {

/// Convex hull, counter-clockwise, of 2D points (monotone chain); collinear points dropped.
std::vector<Vec2> convex_hull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(),
            [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  if (points.size() < 3) return points;
  const auto cross = [](const Vec2& o, const Vec2& a, const Vec2& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

/// A triangle offered for contact, with what the pairing needs.
struct Face {
  int fragment = 0;
  std::array<Vec3, 3> p;
  Vec3 normal = Vec3::Zero();  // unit, outward of its fragment
  double area = 0.0;
  Aabb box;                    // expanded by the tolerance
};

/// Two faces of different fragments that lie on one plane, facing each other; lo of the smaller fragment.
struct FacePair {
  int lo = 0;
  int hi = 0;
};

bool finite(const Vec3& v) { return v.allFinite(); }

bool overlaps(const Aabb& x, const Aabb& y) {
  return (x.min.array() <= y.max.array()).all() && (y.min.array() <= x.max.array()).all();
}

/// Faces a fragment offers: cut-tagged ones, or all when it has none (or when asked).
void collect_faces(const Mesh& mesh, int fragment, bool all_faces, double tol, std::vector<Face>& out) {
  const bool any_cut = std::find(mesh.tags.begin(), mesh.tags.end(), FaceTag::cut) != mesh.tags.end();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!all_faces && any_cut && mesh.tags[t] != FaceTag::cut) continue;
    Face f;
    f.fragment = fragment;
    for (int k = 0; k < 3; ++k) f.p[k] = mesh.vertices[static_cast<std::size_t>(mesh.triangles[t][k])];
    const Vec3 n = (f.p[1] - f.p[0]).cross(f.p[2] - f.p[0]);
    const double len = n.norm();
    if (!(len > 0.0)) continue;
    f.normal = n / len;
    f.area = 0.5 * len;
    for (const Vec3& q : f.p) f.box.extend(q);
    f.box.min.array() -= tol;
    f.box.max.array() += tol;
    out.push_back(f);
  }
}

/// True when faces x and y face each other on one plane (within `tol`).
bool coplanar_opposite(const Face& x, const Face& y, double tol) {
  if (x.normal.dot(y.normal) > -0.5) return false;
  const Face& big = x.area >= y.area ? x : y;  // the larger face's plane is the better-conditioned one
  const Face& small = x.area >= y.area ? y : x;
  for (const Vec3& q : small.p)
    if (std::abs(big.normal.dot(q - big.p[0])) > tol) return false;
  return true;
}

/// All opposite coplanar face pairs, found through a uniform hash grid over the faces' boxes.
std::vector<FacePair> find_face_pairs(const std::vector<Face>& faces, const Aabb& scene, double tol) {
  std::vector<FacePair> pairs;
  if (faces.empty()) return pairs;
  double mean_extent = 0.0;
  for (const Face& f : faces) mean_extent += (f.box.max - f.box.min).maxCoeff();
  const double h = std::max(mean_extent / static_cast<double>(faces.size()), 1e-6 * scene.diagonal());
  auto cell = [&](const Vec3& p) -> Eigen::Array3i {
    return ((p - scene.min).array() / h).floor().cast<int>().max(0);  // clamped: boxes reach tol below min
  };
  auto key = [](const Eigen::Array3i& c) {
    return (static_cast<std::uint64_t>(c.x()) << 42) | (static_cast<std::uint64_t>(c.y()) << 21) |
           static_cast<std::uint64_t>(c.z());
  };
  std::unordered_map<std::uint64_t, std::vector<int>> grid;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const Eigen::Array3i lo = cell(faces[i].box.min);
    const Eigen::Array3i hi = cell(faces[i].box.max);
    for (int x = lo.x(); x <= hi.x(); ++x)
      for (int y = lo.y(); y <= hi.y(); ++y)
        for (int z = lo.z(); z <= hi.z(); ++z) grid[key({x, y, z})].push_back(static_cast<int>(i));
  }
  for (const auto& [cell_key, list] : grid) {
    for (std::size_t i = 0; i < list.size(); ++i) {
      for (std::size_t j = i + 1; j < list.size(); ++j) {
        const Face& x = faces[static_cast<std::size_t>(list[i])];
        const Face& y = faces[static_cast<std::size_t>(list[j])];
        if (x.fragment == y.fragment || !overlaps(x.box, y.box)) continue;
        // Each pair is examined in one cell only: the one holding the lower corner of the boxes' overlap.
        if (key(cell(x.box.min.cwiseMax(y.box.min))) != cell_key) continue;
        if (!coplanar_opposite(x, y, tol)) continue;
        const bool x_lo = x.fragment < y.fragment;
        pairs.push_back({x_lo ? list[i] : list[j], x_lo ? list[j] : list[i]});
      }
    }
  }
  // Hash order is unspecified: sort so that bonds come out in a deterministic order.
  std::sort(pairs.begin(), pairs.end(), [&](const FacePair& u, const FacePair& v) {
    const int fu = faces[static_cast<std::size_t>(u.lo)].fragment, fv = faces[static_cast<std::size_t>(v.lo)].fragment;
    const int gu = faces[static_cast<std::size_t>(u.hi)].fragment, gv = faces[static_cast<std::size_t>(v.hi)].fragment;
    if (fu != fv) return fu < fv;
    if (gu != gv) return gu < gv;
    if (u.lo != v.lo) return u.lo < v.lo;
    return u.hi < v.hi;
  });
  return pairs;
}

/// Section properties of one contact plane from its face pairs; false when the overlap is negligible.
bool make_bond(const std::vector<Face>& faces, const std::vector<FacePair>& group, const SupportGraph& graph,
               double min_area, Bond& bond) {
  // Plane: area-weighted normal and centroid of the lower fragment's faces (each face counted once).
  std::vector<int> lo_faces;
  for (const FacePair& fp : group) lo_faces.push_back(fp.lo);
  std::sort(lo_faces.begin(), lo_faces.end());
  lo_faces.erase(std::unique(lo_faces.begin(), lo_faces.end()), lo_faces.end());
  Vec3 n = Vec3::Zero(), origin = Vec3::Zero();
  double weight = 0.0;
  for (const int f : lo_faces) {
    const Face& face = faces[static_cast<std::size_t>(f)];
    n += face.area * face.normal;
    origin += face.area * (face.p[0] + face.p[1] + face.p[2]) / 3.0;
    weight += face.area;
  }
  n.normalize();
  origin /= weight;
  const Vec3 u = n.unitOrthogonal();
  const Vec3 v = n.cross(u);  // (u, v, n) right-handed: the lower fragment's faces are counter-clockwise
  auto project = [&](const Vec3& q) { return Vec2(u.dot(q - origin), v.dot(q - origin)); };

  AreaMoments moments;
  std::vector<Vec2> corners;  // vertices of every overlap polygon, for the fibre distances
  for (const FacePair& fp : group) {
    const Face& lo = faces[static_cast<std::size_t>(fp.lo)];
    const Face& hi = faces[static_cast<std::size_t>(fp.hi)];
    const std::vector<Vec2> subject = {project(lo.p[0]), project(lo.p[1]), project(lo.p[2])};
    const std::vector<Vec2> clip = {project(hi.p[0]), project(hi.p[2]), project(hi.p[1])};  // reversed: ccw
    const std::vector<Vec2> overlap = clip_convex(subject, clip);
    if (overlap.empty()) continue;
    moments.add_polygon(overlap);
    corners.insert(corners.end(), overlap.begin(), overlap.end());
  }
  if (!(moments.area > min_area)) return false;

  const PrincipalSection s = principal_section(moments);
  bond.a = faces[static_cast<std::size_t>(group.front().lo)].fragment;
  bond.b = faces[static_cast<std::size_t>(group.front().hi)].fragment;
  bond.area = moments.area;
  bond.normal = n;
  bond.centroid = origin + s.centroid.x() * u + s.centroid.y() * v;
  bond.axis_1 = s.axis_1.x() * u + s.axis_1.y() * v;
  bond.axis_2 = n.cross(bond.axis_1);
  bond.moment_1 = s.moment_1;
  bond.moment_2 = s.moment_2;
  bond.polar_moment = s.moment_1 + s.moment_2;
  for (const Vec2& q : corners) {
    const Vec2 d = q - s.centroid;
    bond.fibre_1 = std::max(bond.fibre_1, std::abs(d.dot(s.axis_2)));  // distance from axis_1
    bond.fibre_2 = std::max(bond.fibre_2, std::abs(d.dot(s.axis_1)));  // distance from axis_2
    bond.radius = std::max(bond.radius, d.norm());
  }
  std::vector<Vec2> in_axes;
  in_axes.reserve(corners.size());
  for (const Vec2& q : corners) {
    const Vec2 d = q - s.centroid;
    in_axes.emplace_back(d.dot(s.axis_1), d.dot(s.axis_2));
  }
  bond.section = convex_hull(std::move(in_axes));
  // Spring length: the two bodies' centroids to the contact plane, never below 1e-3 of sqrt(area).
  const double to_a = std::abs(n.dot(bond.centroid - graph.nodes[static_cast<std::size_t>(bond.a)].centroid));
  const double to_b = std::abs(n.dot(graph.nodes[static_cast<std::size_t>(bond.b)].centroid - bond.centroid));
  bond.length = std::max(to_a + to_b, 1e-3 * std::sqrt(bond.area));
  return true;
}

}  // namespace

void index_bonds(SupportGraph& graph) {
  graph.node_bonds.assign(graph.nodes.size(), {});
  for (std::size_t i = 0; i < graph.bonds.size(); ++i) {
    const Bond& e = graph.bonds[i];
    assert(e.a >= 0 && e.a < e.b && e.b < graph.node_count());
    graph.node_bonds[static_cast<std::size_t>(e.a)].push_back(static_cast<int>(i));
    graph.node_bonds[static_cast<std::size_t>(e.b)].push_back(static_cast<int>(i));
  }
}

Result<SupportGraph> build_support_graph(std::span<const Fragment> fragments, std::span<const Aabb> anchors,
                                         const SupportGraphSettings& settings) {
  if (!(settings.density > 0.0) || !std::isfinite(settings.density))
    return Error{"support graph: density must be finite and > 0 (got " + std::to_string(settings.density) + ")"};
  if (!(settings.relative_tolerance > 0.0 && settings.relative_tolerance < 1e-2))
    return Error{"support graph: relative_tolerance must be in (0, 0.01)"};
  if (!(settings.min_relative_area >= 0.0 && settings.min_relative_area < 1.0))
    return Error{"support graph: min_relative_area must be in [0, 1)"};
  for (std::size_t i = 0; i < anchors.size(); ++i)
    if (!finite(anchors[i].min) || !finite(anchors[i].max) || (anchors[i].min.array() > anchors[i].max.array()).any())
      return Error{"support graph: anchor " + std::to_string(i) + " is not a finite box with min <= max"};

  SupportGraph graph;
  Aabb scene;
  std::vector<Aabb> boxes;
  for (std::size_t f = 0; f < fragments.size(); ++f) {
    const Fragment& frag = fragments[f];
    for (const Vec3& q : frag.mesh.vertices)
      if (!finite(q)) return Error{"support graph: fragment " + std::to_string(f) + " has a non-finite vertex"};
    if (!(frag.mass.volume > 0.0) || !frag.mass.centroid.allFinite() || !frag.mass.inertia.allFinite())
      return Error{"support graph: fragment " + std::to_string(f) + " has no positive finite volume"};
    SupportNode node;
    node.volume = frag.mass.volume;
    node.mass = settings.density * frag.mass.volume;
    node.centroid = frag.mass.centroid;
    node.inertia = settings.density * frag.mass.inertia;
    const Aabb box = bounding_box(frag.mesh);
    for (const Aabb& anchor : anchors) node.anchored = node.anchored || overlaps(box, anchor);
    boxes.push_back(box);
    scene.extend(box.min);
    scene.extend(box.max);
    graph.nodes.push_back(node);
  }
  const double diag = scene.diagonal();
  const double tol = settings.relative_tolerance * diag;

  std::vector<Face> faces;
  for (std::size_t f = 0; f < fragments.size(); ++f)
    collect_faces(fragments[f].mesh, static_cast<int>(f), settings.all_faces, tol, faces);
  const std::vector<FacePair> pairs = find_face_pairs(faces, scene, tol);

  // Split each fragment pair's face pairs by plane, then make one bond per plane.
  std::size_t begin = 0;
  while (begin < pairs.size()) {
    const int fa = faces[static_cast<std::size_t>(pairs[begin].lo)].fragment;
    const int fb = faces[static_cast<std::size_t>(pairs[begin].hi)].fragment;
    std::size_t end = begin;
    while (end < pairs.size() && faces[static_cast<std::size_t>(pairs[end].lo)].fragment == fa &&
           faces[static_cast<std::size_t>(pairs[end].hi)].fragment == fb)
      ++end;
    std::vector<std::vector<FacePair>> planes;
    for (std::size_t k = begin; k < end; ++k) {
      const Face& lo = faces[static_cast<std::size_t>(pairs[k].lo)];
      auto same_plane = [&](const std::vector<FacePair>& plane) {
        const Face& ref = faces[static_cast<std::size_t>(plane.front().lo)];
        if (ref.normal.dot(lo.normal) < 0.99) return false;
        for (const Vec3& q : lo.p)
          if (std::abs(ref.normal.dot(q - ref.p[0])) > 10.0 * tol) return false;
        return true;
      };
      auto it = std::find_if(planes.begin(), planes.end(), same_plane);
      if (it == planes.end()) planes.push_back({pairs[k]});
      else it->push_back(pairs[k]);
    }
    for (const std::vector<FacePair>& plane : planes) {
      Bond bond;
      if (make_bond(faces, plane, graph, settings.min_relative_area * diag * diag, bond)) graph.bonds.push_back(bond);
    }
    begin = end;
  }
  index_bonds(graph);
  return graph;
}

Result<SupportGraph> build_support_graph(std::span<const Mesh> meshes, std::span<const Aabb> anchors,
                                         const SupportGraphSettings& settings) {
  std::vector<Fragment> fragments;
  fragments.reserve(meshes.size());
  for (const Mesh& m : meshes) fragments.push_back({m, mass_properties(m)});
  return build_support_graph(fragments, anchors, settings);
}

}  // namespace shatter
