// Hostile inputs, no crash and no hang inside the limits: coordinates an algorithm cannot represent are
// refused before it runs (through every command and through the library), polygon faces of any size
// are triangulated in O(n log n) with the right answer, and the Voronoi neighbour search is local.

#include "tests/hostile/hostile_support.h"
#include "algorithms/core/mesh_io.h"
#include "algorithms/core/polygon_triangulation.h"
#include "algorithms/core/predicates.h"
#include "algorithms/core/primitives.h"
#include "algorithms/core/random.h"
#include "algorithms/core/representable_range.h"
#include "algorithms/fracture/plane_slice/plane_slice_fracturer.h"
#include "algorithms/fracture/voronoi/voronoi_cells.h"
#include "algorithms/fracture/voronoi/voronoi_fracturer.h"
#include "tests/support/builtin_registries.h"
#include "tests/support/cli_runner.h"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <string>
#include <vector>

using namespace shatter;
using Catch::Matchers::Contains;
using shatter::test::line_count;
using shatter::test::run_cli_argv;

namespace fs = std::filesystem;
using shatter::test::hostile_scratch;
using shatter::test::put_file;

namespace {

/// A unit cube scaled by `scale` about the origin and moved by `offset`, as an OFF file.
fs::path cube_off(const fs::path& path, double scale, double offset = 0.0) {
  Mesh cube = make_box(Vec3(1, 1, 1));
  for (Vec3& p : cube.vertices) p = scale * p + Vec3::Constant(offset);
  REQUIRE(write_off(cube, path).ok());
  return path;
}

void require_refused(const std::vector<std::string>& args, const std::string& word) {
  const auto r = run_cli_argv(args);
  std::string command;
  for (const std::string& a : args) command += a + " ";
  INFO(command << "\n" << r.err);
  CHECK(r.exit_code == 2);
  CHECK(line_count(r.err) == 1);
  CHECK(r.err.rfind("shatterbench: error: ", 0) == 0);
  CHECK_THAT(r.err, Contains(word));
}

/// Winding number of `poly` around `p` (non-zero: inside).
int winding(const std::vector<Vec2>& poly, const Vec2& p) {
  int w = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % poly.size()];
    if (a.y() <= p.y()) {
      if (b.y() > p.y() && orient2d(a, b, p) > 0) ++w;
    } else if (b.y() <= p.y() && orient2d(a, b, p) < 0) {
      --w;
    }
  }
  return w;
}

double shoelace(const std::vector<Vec2>& poly) {
  double twice = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % poly.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

/// Checks a triangulation of the simple polygon `poly` (counter-clockwise when `ccw`) against the
/// known answers: n - 2 triangles, each turning like the polygon and inside it, every polygon edge
/// used once in its direction, and the areas summing to the shoelace area.
void check_triangulation(const std::string& name, std::vector<Vec2> poly, bool ccw) {
  if (!ccw) std::reverse(poly.begin(), poly.end());
  const std::size_t n = poly.size();
  // Lifted onto a tilted plane z = 0.3 x - 0.2 y: the projection drops z, as the reader's does.
  std::vector<Vec3> vertices;
  for (const Vec2& p : poly) vertices.emplace_back(p.x(), p.y(), 0.3 * p.x() - 0.2 * p.y());
  std::vector<std::int32_t> corners(n);
  for (std::size_t i = 0; i < n; ++i) corners[i] = static_cast<std::int32_t>(i);
  std::vector<Triangle> triangles;
  INFO(name << " with " << n << " corners, " << (ccw ? "counter-clockwise" : "clockwise"));
  REQUIRE(triangulate_polygon(vertices, corners, triangles).ok());
  CHECK(triangles.size() == n - 2);
  const int sign = ccw ? 1 : -1;
  double area = 0.0;
  int wrong_turn = 0, outside = 0;
  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : triangles) {
    const Vec2 &a = poly[static_cast<std::size_t>(t[0])], &b = poly[static_cast<std::size_t>(t[1])],
               &c = poly[static_cast<std::size_t>(t[2])];
    wrong_turn += orient2d(a, b, c) != sign;
    area += 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    outside += winding(poly, (a + b + c) / 3.0) == 0;
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  CHECK(wrong_turn == 0);
  CHECK(outside == 0);
  CHECK(area == Approx(shoelace(poly)).epsilon(1e-9));
  int edges_missing = 0;
  for (std::size_t i = 0; i < n; ++i)
    edges_missing += directed[{static_cast<int>(i), static_cast<int>((i + 1) % n)}] != 1;
  CHECK(edges_missing == 0);
}

/// A star of `points` spikes between radii 1 and `inner`, counter-clockwise.
std::vector<Vec2> star(int points, double inner) {
  std::vector<Vec2> out;
  for (int i = 0; i < 2 * points; ++i) {
    const double angle = std::numbers::pi * i / points;
    const double r = i % 2 == 0 ? 1.0 : inner;
    out.emplace_back(r * std::cos(angle), r * std::sin(angle));
  }
  return out;
}

/// A comb: a spine along the bottom and `teeth` narrow teeth pointing up, counter-clockwise.
std::vector<Vec2> comb(int teeth) {
  std::vector<Vec2> out = {{0, 0}, {2.0 * teeth, 0}};
  for (int i = teeth - 1; i >= 0; --i) {
    out.emplace_back(2.0 * i + 1.5, 1.0);
    out.emplace_back(2.0 * i + 1.5, 10.0);
    out.emplace_back(2.0 * i + 0.5, 10.0);
    out.emplace_back(2.0 * i + 0.5, 1.0);
  }
  out.emplace_back(0, 1.0);
  return out;
}

/// A thick spiral strip of `turns` turns with `steps` corners on each side, counter-clockwise.
std::vector<Vec2> spiral(int steps, double turns) {
  std::vector<Vec2> outer, inner;
  for (int i = 0; i <= steps; ++i) {
    const double t = turns * 2.0 * std::numbers::pi * i / steps;
    const double r = 1.0 + t;
    outer.emplace_back(r * std::cos(t), r * std::sin(t));
    inner.emplace_back((r + 2.5) * std::cos(t), (r + 2.5) * std::sin(t));
  }
  std::vector<Vec2> out(outer.rbegin(), outer.rend());
  out.insert(out.end(), inner.begin(), inner.end());
  return out;
}

/// A random star-shaped polygon: sorted random angles, random radii in [0.1, 1].
std::vector<Vec2> random_star(int corners, std::uint64_t seed) {
  SplitMix64 rng(seed);
  std::vector<double> angles;
  for (int i = 0; i < corners; ++i) angles.push_back(2.0 * std::numbers::pi * rng.uniform());
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  std::vector<Vec2> out;
  for (const double a : angles) {
    const double r = 0.1 + 0.9 * rng.uniform();
    out.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return out;
}

}  // namespace

TEST_CASE("no crash: coordinates outside the representable range are refused by every command",
          "[hostile][no_crash][cli]") {
  const fs::path dir = hostile_scratch("range");
  struct Far {
    std::string name;
    double scale, offset;
  };
  // 1e80 and 1e100 crashed cgal-clip with SIGFPE, 1e150 with SIGSEGV; 1e100 and 1e308 overflowed the
  // mass properties; 2.5e9 puts the corners just past the range, 1e-7 below the smallest extent.
  const std::vector<Far> far = {{"1e80", 1e80, 0.0},   {"1e100", 1e100, 0.0}, {"1e150", 1e150, 0.0},
                                {"1e308", 1e308, 0.0}, {"2.5e9", 2.5e9, 0.0}, {"offset", 1.0, 3e9},
                                {"tiny", 1e-7, 0.0}};
  for (const Far& f : far) {
    const std::string mesh = cube_off(dir / (f.name + ".off"), f.scale, f.offset).string();
    const std::string word = f.name == "tiny" ? "extent" : "representable range";
    for (const char* algo : {"cgal-clip", "plane-slice", "voronoi", "fem-lite"})
      require_refused({"fracture", "--mesh", mesh, "--algo", algo, "--fragments", "5"}, word);
    require_refused({"table", "--mesh", mesh, "--fragments", "5", "--repetitions", "1"}, word);
    const std::string case_file =
        put_file(dir / (f.name + ".json"), R"({"mesh": {"file": ")" + mesh + R"("}, "impacts": [{"frame": 1,)"
                                        R"( "point": [0, 0, 0], "direction": [0, 0, -1], "impulse": 10}]})")
            .string();
    require_refused({"accuracy", "--case", case_file, "--family", "fracture", "--repetitions", "1"}, word);
    require_refused({"grid", "--case", case_file, "--prefracture", "2", "--runtime", "2", "--repetitions", "1",
                     "--frames", "2", "--no-cache"},
                    word);
  }
  // A case that scales a plain unit cube out of range, and a primitive out of range.
  const std::string unit = cube_off(dir / "unit.off", 1.0).string();
  const std::string scaled = put_file(dir / "scaled.json", R"({"mesh": {"file": ")" + unit + R"(", "scale": 1e90}})").string();
  const std::string moved = put_file(dir / "moved.json", R"({"mesh": {"file": ")" + unit + R"(", "translate": [0, 0, 1e12]}})").string();
  const std::string box = put_file(dir / "box.json", R"({"mesh": {"box": {"size": [1e100, 1, 1]}}})").string();
  const std::string sphere = put_file(dir / "sphere.json", R"({"mesh": {"sphere": {"radius": 1e-9}}})").string();
  // The case's own keys are held to their physical ranges first, naming the key ...
  for (const std::string& c : {scaled, moved, box})
    require_refused({"grid", "--case", c, "--prefracture", "2", "--runtime", "2", "--repetitions", "1", "--frames", "2",
                     "--no-cache"},
                    "must be in");
  // ... and a mesh that in-range keys carry out of the representable range is refused where it enters.
  const std::string distant = cube_off(dir / "far.off", 1e8).string();
  const std::string far_scaled =
      put_file(dir / "far_scaled.json", R"({"mesh": {"file": ")" + distant + R"(", "scale": 1e3}})").string();
  require_refused({"grid", "--case", far_scaled, "--prefracture", "2", "--runtime", "2", "--repetitions", "1",
                   "--frames", "2", "--no-cache"},
                  "representable range");
  require_refused({"grid", "--case", sphere, "--prefracture", "2", "--runtime", "2", "--repetitions", "1", "--frames",
                   "2", "--no-cache"},
                  "must be in");
  const std::string tiny = cube_off(dir / "tiny.off", 1e-7).string();
  const std::string tiny_case = put_file(dir / "tiny.json", R"({"mesh": {"file": ")" + tiny + R"("}})").string();
  require_refused({"grid", "--case", tiny_case, "--prefracture", "2", "--runtime", "2", "--repetitions", "1",
                   "--frames", "2", "--no-cache"},
                  "extent");
}

TEST_CASE("no crash: every fracturer called directly refuses coordinates outside the range", "[hostile][no_crash]") {
  const Registries r = test::builtin_registries();
  for (const double scale : {1e80, 1e150, 1e300, 3e9}) {
    Mesh cube = make_box(Vec3(1, 1, 1));
    for (Vec3& p : cube.vertices) p *= scale;
    for (const std::string& name : r.fracturers.names()) {
      auto fracturer = r.fracturers.create(name);
      REQUIRE(fracturer.ok());
      FractureParams params;
      params.fragments = 5;
      const Result<std::vector<Fragment>> pieces = (*fracturer)->fracture(cube, params);
      INFO(name << " at scale " << scale);
      REQUIRE_FALSE(pieces.ok());
      CHECK_THAT(pieces.error().message, Contains(name) && Contains("representable range"));
    }
  }
  // The other entry points: planes, sites and impacts out of range.
  const Mesh cube = make_box(Vec3(1, 1, 1));
  const PlaneSliceFracturer slicer;
  const Plane far_plane{Vec3(1e80, 0, 0), Vec3(1, 0, 0)};
  CHECK_FALSE(slicer.fracture_by_planes(cube, std::span(&far_plane, 1), 10).ok());
  const Plane huge_normal{Vec3(0, 0, 0), Vec3(1e200, 1e200, 0)};
  CHECK_FALSE(slicer.fracture_by_planes(cube, std::span(&huge_normal, 1), 10).ok());
  Mesh far_cube = cube;
  for (Vec3& p : far_cube.vertices) p *= 1e100;
  const Plane unit_plane{Vec3(0, 0, 0), Vec3(1, 0, 0)};
  CHECK_FALSE(slicer.fracture_by_planes(far_cube, std::span(&unit_plane, 1), 10).ok());
  const VoronoiFracturer voronoi;
  const std::vector<Vec3> sites = {Vec3(0.1, 0, 0), Vec3(-0.1, 0, 0), Vec3(1e120, 0, 0)};
  const Result<std::vector<Fragment>> by_sites = voronoi.fracture_with_sites(cube, sites);
  REQUIRE_FALSE(by_sites.ok());
  CHECK_THAT(by_sites.error().message, Contains("site 2"));
  FractureParams hit;
  hit.fragments = 4;
  hit.impact = Impact{Vec3(0, 0, 1e200), -Vec3::UnitZ(), 1.0, 0.0};
  CHECK_FALSE(voronoi.fracture(cube, hit).ok());
  hit.impact = Impact{Vec3(0, 0, 0), -Vec3::UnitZ(), 1.0, 1e300};
  CHECK_FALSE(voronoi.fracture(cube, hit).ok());
  // At the edge of the range a solid is accepted.
  Mesh edge = cube;
  for (Vec3& p : edge.vertices) p = 1e8 * p + Vec3::Constant(9e8 - 1e8);
  CHECK(check_representable(edge, "edge").ok());
  CHECK(slicer.fracture(edge, FractureParams{}).ok());
}

TEST_CASE("no crash: polygon faces are triangulated into n - 2 triangles that cover them exactly",
          "[hostile][no_crash][mesh_io]") {
  for (const bool ccw : {true, false}) {
    for (const int n : {3, 5, 50, 1000}) check_triangulation("star", star(n, 0.3), ccw);
    for (const int n : {2, 25, 400}) check_triangulation("comb", comb(n), ccw);
    for (const int n : {40, 800}) check_triangulation("spiral", spiral(n, 3.0), ccw);
    for (const std::uint64_t seed : {1u, 2u, 3u}) check_triangulation("random star", random_star(2000, seed), ccw);
    check_triangulation("concave quad", {{0, 0}, {2, 0}, {1, 0.3}, {1, 2}}, ccw);
    check_triangulation("collinear corners", {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {2, 1}, {1.5, 0.5}, {1, 1}, {0, 1}}, ccw);
  }
  // A polygon that crosses itself has no triangulation that keeps its edges: an error, not a guess.
  std::vector<Vec3> bow_tie = {{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 1, 0}};  // unequal lobes: a non-zero normal
  std::vector<Triangle> out;
  const std::vector<std::int32_t> four = {0, 1, 2, 3};
  CHECK_THAT(triangulate_polygon(bow_tie, four, out).error().message, Contains("crosses itself"));
  // A corner beyond the representable range: refused before the exact predicates could overflow.
  const std::vector<Vec3> far = {{0, 0, 0}, {1, 0, 0}, {1, 1e175, 0}, {0, 1, 0}, {0.5, 0.5, 0}};
  const std::vector<std::int32_t> far_corners = {0, 1, 2, 3, 4};
  CHECK_THAT(triangulate_polygon(far, far_corners, out).error().message, Contains("representable range"));
  std::vector<Vec3> pentagram;
  for (int i = 0; i < 5; ++i) {
    const double a = 4.0 * std::numbers::pi * i / 5;
    pentagram.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  const std::vector<std::int32_t> five = {0, 1, 2, 3, 4};
  CHECK_FALSE(triangulate_polygon(pentagram, five, out).ok());

  // Through the readers: one OFF face and one OBJ face of 20,000 corners, and a face past the limit.
  const fs::path dir = hostile_scratch("polygons");
  const std::vector<Vec2> big = star(10000, 0.5);
  std::string off = "OFF\n" + std::to_string(big.size()) + " 1 0\n", obj, face = std::to_string(big.size()), obj_face = "f";
  char line[96];
  for (std::size_t i = 0; i < big.size(); ++i) {
    std::snprintf(line, sizeof line, "%.17g %.17g 0\n", big[i].x(), big[i].y());
    off += line;
    obj += "v ";
    obj += line;
    face += ' ';
    face += std::to_string(i);
    obj_face += ' ';
    obj_face += std::to_string(i + 1);
  }
  const Result<Mesh> from_off = read_off(put_file(dir / "star.off", off + face + "\n"));
  REQUIRE(from_off.ok());
  CHECK(from_off->triangle_count() == big.size() - 2);
  CHECK(surface_area(*from_off) == Approx(shoelace(big)).epsilon(1e-9));
  const Result<Mesh> from_obj = read_obj(put_file(dir / "star.obj", obj + obj_face + "\n"));
  REQUIRE(from_obj.ok());
  CHECK(from_obj->triangle_count() == big.size() - 2);
  const std::string over = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n" + std::to_string(kMaxPolygonCorners + 1) + " 0 1 2\n";
  const Result<Mesh> refused = read_off(put_file(dir / "over.off", over));
  REQUIRE_FALSE(refused.ok());
  CHECK_THAT(refused.error().message, Contains(":6: ") && Contains("limit of 1000000 corners per polygon"));
}

TEST_CASE("no crash: the Voronoi neighbour search gives the cells of a full sort", "[hostile][no_crash][voronoi]") {
  // The reference: every other site sorted by (squared distance, index), as the cells were computed
  // before the grid search; the grid must give the very same neighbour lists and boxes.
  const auto reference = [](std::span<const Vec3> sites, const Aabb& box, double margin) {
    const int n = static_cast<int>(sites.size());
    std::vector<VoronoiCell> cells(sites.size());
    for (int i = 0; i < n; ++i) {
      const Vec3& s = sites[static_cast<std::size_t>(i)];
      std::vector<std::pair<double, std::int32_t>> order;
      for (int j = 0; j < n; ++j)
        if (j != i) order.emplace_back((sites[static_cast<std::size_t>(j)] - s).squaredNorm(), j);
      std::sort(order.begin(), order.end());
      VoronoiCell& cell = cells[static_cast<std::size_t>(i)];
      cell.polytope = box_polytope(box);
      double r2 = max_corner_distance_squared(cell.polytope, s);
      for (std::size_t k = 0; k < order.size(); ++k) {
        if (order[k].first > 4.0 * r2) break;
        clip_polytope(cell.polytope, bisector_plane(sites, i, order[k].second), static_cast<int>(k));
        if (!cell.polytope.ok) break;
        r2 = max_corner_distance_squared(cell.polytope, s);
      }
      if (!cell.polytope.ok) r2 = max_corner_distance_squared(box_polytope(box), s);
      const double reach = std::sqrt(r2) + margin;
      for (const auto& [d2, j] : order) {
        if (d2 > 4.0 * reach * reach) break;
        cell.neighbours.push_back(j);
      }
    }
    return cells;
  };
  SplitMix64 rng(7);
  const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
  std::map<std::string, std::vector<Vec3>> sets;
  for (int i = 0; i < 400; ++i) sets["uniform"].emplace_back(uniform(-1, 1), uniform(-2, 2), uniform(0, 0.1));
  for (int i = 0; i < 300; ++i)
    sets["clusters"].emplace_back(Vec3(i % 2 == 0 ? -5 : 5, 0, 0) + Vec3(uniform(-0.1, 0.1), uniform(-0.1, 0.1), uniform(-0.1, 0.1)));
  for (int i = 0; i < 200; ++i) sets["plane"].emplace_back(uniform(-1, 1), uniform(-1, 1), 0.0);
  for (int i = 0; i < 60; ++i) sets["line"].emplace_back(uniform(-1, 1), 0.0, 0.0);
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 6; ++y)
      for (int z = 0; z < 6; ++z) sets["lattice"].emplace_back(x, y, z);  // ties broken by index
  sets["one"] = {Vec3(0, 0, 0)};
  sets["two"] = {Vec3(0, 0, 0), Vec3(1e-6, 0, 0)};
  for (const auto& [name, sites] : sets) {
    INFO(name);
    Aabb box;
    for (const Vec3& s : sites) box.extend(s);
    box.min.array() -= 0.5;
    box.max.array() += 0.5;
    const double margin = 1e-9;
    const std::vector<VoronoiCell> grid = voronoi_cells(sites, box, margin);
    const std::vector<VoronoiCell> full = reference(sites, box, margin);
    REQUIRE(grid.size() == full.size());
    int differ = 0;
    for (std::size_t i = 0; i < grid.size(); ++i) differ += grid[i].neighbours != full[i].neighbours;
    CHECK(differ == 0);
  }
}
