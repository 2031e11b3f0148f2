#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_io.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"
#include "tests/support/mesh_fixtures.h"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace shatter;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

/// A file in the temporary folder, named after the test so that parallel test processes never share.
std::filesystem::path temp_file(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("shatter_mesh_io_" + name);
}

std::filesystem::path write_temp(const std::string& name, const std::string& text) {
  const std::filesystem::path path = temp_file(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string read_error(const std::filesystem::path& path) {
  const Result<Mesh> mesh = read_mesh(path);
  return mesh.ok() ? std::string("(no error)") : mesh.error().message;
}

/// Signed area of a triangle's projection on the xy plane.
double area_xy(const Mesh& mesh, const Triangle& t) {
  const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
  return 0.5 * ((b - a).cross(c - a)).z();
}

}  // namespace

TEST_CASE("mesh_io: OFF round trip is bit-exact", "[mesh_io]") {
  Mesh mesh = make_sphere(1.0 / 3.0, 7, 5, Vec3(0.1, 1e6 + 0.7, -2.0 / 3.0));
  mesh.vertices[0] = Vec3(5e-324, -1e300, 0.1 + 0.2);  // denormal, huge, not a short decimal
  const std::filesystem::path path = temp_file("roundtrip.off");
  REQUIRE(write_off(mesh, path).ok());
  const Result<Mesh> back = read_off(path);
  REQUIRE(back.ok());
  CHECK(back->vertices == mesh.vertices);
  CHECK(back->triangles == mesh.triangles);
  CHECK(back->tags == std::vector<FaceTag>(mesh.triangles.size(), FaceTag::surface));
}

TEST_CASE("mesh_io: OBJ round trip keeps positions and cut tags", "[mesh_io]") {
  Mesh mesh = make_box(Vec3(1.0 / 3.0, 0.7, 1e-3), Vec3(1e5 + 0.1, 0.2, 0.3));
  for (std::size_t f = 0; f < mesh.tags.size(); f += 3) mesh.tags[f] = FaceTag::cut;
  const std::filesystem::path path = temp_file("roundtrip.obj");
  REQUIRE(write_obj(mesh, path).ok());
  const Result<Mesh> back = read_obj(path);
  REQUIRE(back.ok());
  CHECK(back->vertices == mesh.vertices);
  // Faces come back grouped (surface, then cut): compare as sets of (triangle, tag).
  auto faces = [](const Mesh& m) {
    std::vector<std::tuple<Triangle, FaceTag>> out;
    for (std::size_t f = 0; f < m.triangles.size(); ++f) out.emplace_back(m.triangles[f], m.tags[f]);
    std::sort(out.begin(), out.end());
    return out;
  };
  CHECK(faces(*back) == faces(mesh));
  CHECK(tagged_area(*back, FaceTag::cut) == Approx(tagged_area(mesh, FaceTag::cut)).epsilon(1e-15));
}

TEST_CASE("mesh_io: polygons are triangulated with their winding, convex or not", "[mesh_io]") {
  // U shape: the 3 x 2 rectangle minus the unit notch at the top middle, area 5, counter-clockwise.
  // A fan from the first corner would fold over the notch.
  const std::string off = "OFF\n8 1 0\n0 0 0\n3 0 0\n3 2 0\n2 2 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n";
  for (const bool reversed : {false, true}) {
    const std::string face = reversed ? "8 7 6 5 4 3 2 1 0\n" : "8 0 1 2 3 4 5 6 7\n";
    const Result<Mesh> mesh = read_off(write_temp(reversed ? "u_cw.off" : "u_ccw.off", off + face));
    REQUIRE(mesh.ok());
    REQUIRE(mesh->triangle_count() == 6);
    double area = 0.0;
    for (const Triangle& t : mesh->triangles) {
      const double a = area_xy(*mesh, t) * (reversed ? -1.0 : 1.0);
      CHECK(a > 0.0);  // every triangle turns like the polygon
      area += a;
    }
    CHECK(area == Approx(5.0).epsilon(1e-15));
  }
  // A convex quad in the plane x = 1 gives a fan of 2 triangles of total area 2 x 3.
  const Result<Mesh> quad = read_off(write_temp("quad.off", "OFF\n4 1 0\n1 0 0\n1 2 0\n1 2 3\n1 0 3\n4 0 1 2 3\n"));
  REQUIRE(quad.ok());
  CHECK(quad->triangle_count() == 2);
  CHECK(surface_area(*quad) == Approx(6.0).epsilon(1e-15));
}

TEST_CASE("mesh_io: OFF comments, blank lines, colours and header variants are accepted", "[mesh_io]") {
  const std::string text =
      "# leading comment\n\nCOFF\n4 4 6   # counts\n\n"
      "0 0 0 255 0 0 255\n1 0 0 0 255 0 255#glued comment\n0 1 0 0 0 255 255\n0 0 1 9 9 9 255\n\n"
      "3 0 2 1 0.9 0 0\n3 0 1 3  1 1 1\n3 0 3 2\n3 1 2 3 # last\n\n# trailing comment\n";
  Result<Mesh> mesh = read_off(write_temp("colours.off", text));
  REQUIRE(mesh.ok());
  CHECK(mesh->vertices.size() == 4);
  CHECK(mesh->vertices[3] == Vec3(0, 0, 1));
  REQUIRE(validate_solid(*mesh, "colours.off").ok());
  CHECK(signed_volume(*mesh) == Approx(1.0 / 6.0).epsilon(1e-15));
  // Counts on the header line.
  CHECK(read_off(write_temp("inline.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")).ok());
}

TEST_CASE("mesh_io: malformed OFF files give errors naming file and line", "[mesh_io]") {
  const std::string tet = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  auto check = [](const std::string& name, const std::string& text, const std::string& line, const std::string& what) {
    const std::filesystem::path path = write_temp(name, text);
    const std::string message = read_error(path);
    INFO(message);
    CHECK_THAT(message, StartsWith(path.string() + ":" + line + ": ") && Contains(what));
  };
  check("garbage.off", "OFF\n4 4 0\n0 0 0\n1 zero 0\n0 1 0\n0 0 1\n" + faces, "4", "non-numeric token 'zero'");
  check("range.off", "OFF\n4 4 0\n" + tet + "3 0 2 1\n3 0 1 4\n3 0 3 2\n3 1 2 3\n", "8", "vertex index 4 out of range");
  check("negative.off", "OFF\n-4 4 0\n" + tet + faces, "2", "negative count");
  check("absurd.off", "OFF\n4 60000000 0\n" + tet + faces, "2", "exceeds the limit");
  check("header.off", "PLY\n4 4 0\n" + tet + faces, "1", "expected header 'OFF'");
  check("binary.off", "OFF BINARY\n", "1", "binary OFF");
  check("extra.off", "OFF\n4 4 0\n" + tet + faces + "3 1 2 0\n", "11", "count mismatch");
  check("short_face.off", "OFF\n4 4 0\n" + tet + "2 0 1\n", "7", "2 corners");
  check("missing_index.off", "OFF\n4 4 0\n" + tet + "3 0 1\n", "7", "declares 3 corners but lists 2");
  check("float_index.off", "OFF\n4 4 0\n" + tet + "3 0 1 2.0\n", "7", "non-numeric token '2.0'");
  check("few_vertices.off", "OFF\n4 4 0\n" + tet.substr(0, 12), "4", "truncated file: expected 4 vertices, found 2");
  check("empty.off", "", "0", "empty file");
  CHECK_THAT(read_error(temp_file("does_not_exist.off")), Contains("cannot open"));
  CHECK_THAT(read_error(temp_file("mesh.stl")), Contains("unknown mesh format"));
}

TEST_CASE("mesh_io: an OFF header announcing counts past the limits is refused before allocating",
          "[mesh_io][limits]") {
  // 30 bytes announcing 4e9 faces or 2e7 vertices: refused at the header, not on truncation.
  const std::string faces = read_error(write_temp("many_faces.off", "OFF\n4 4000000000 0\n0 0 0\n"));
  CHECK_THAT(faces, StartsWith(temp_file("many_faces.off").string() + ":2: ") &&
                        Contains("face count 4000000000 exceeds the limit of 10000000 triangles per mesh"));
  const std::string vertices = read_error(write_temp("many_vertices.off", "OFF\n20000000 4 0\n0 0 0\n"));
  CHECK_THAT(vertices, StartsWith(temp_file("many_vertices.off").string() + ":2: ") &&
                           Contains("vertex count 20000000 exceeds the limit of 10000000 vertices per mesh"));
  // At the limits the header is accepted, and the short file is then refused as truncated.
  CHECK_THAT(read_error(write_temp("at_limit.off", "OFF\n10000000 10000000 0\n0 0 0\n")), Contains("truncated file"));
}

TEST_CASE("mesh_io: triangles after triangulation, vertices and file size are held to the limits",
          "[mesh_io][limits]") {
  // A cube of six quads: 8 vertices, 12 triangles, 136 bytes as OFF.
  const std::string cube_off =
      "OFF\n8 6 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
      "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";
  const std::filesystem::path off = write_temp("cube_limits.off", cube_off);
  REQUIRE(read_off(off).ok());
  CHECK(read_off(off, {.max_triangles = 12}).ok());
  const Result<Mesh> over = read_off(off, {.max_triangles = 11});
  REQUIRE_FALSE(over.ok());
  CHECK_THAT(over.error().message,
             StartsWith(off.string() + ":16: ") &&
                 Contains("face 5: triangle count (after triangulation) exceeds the limit of 11"));
  const Result<Mesh> small = read_off(off, {.max_file_bytes = 100});
  REQUIRE_FALSE(small.ok());
  CHECK_THAT(small.error().message, StartsWith(off.string() + ": larger than the limit of 100 bytes per mesh file"));

  const std::filesystem::path obj = write_temp("quads_limits.obj", "v 0 0 0\nv 2 0 0\nv 2 3 0\nv 0 3 0\nf 1 2 3 4\n");
  REQUIRE(read_obj(obj).ok());
  CHECK(read_obj(obj, {.max_triangles = 2, .max_vertices = 4}).ok());
  const Result<Mesh> triangles = read_obj(obj, {.max_triangles = 1});
  REQUIRE_FALSE(triangles.ok());
  CHECK_THAT(triangles.error().message, StartsWith(obj.string() + ":5: ") &&
                                            Contains("triangle count (after triangulation) exceeds the limit of 1"));
  const Result<Mesh> vertices = read_obj(obj, {.max_vertices = 3});
  REQUIRE_FALSE(vertices.ok());
  CHECK_THAT(vertices.error().message,
             StartsWith(obj.string() + ":4: ") && Contains("vertex count exceeds the limit of 3 vertices per mesh"));
  const Result<Mesh> bytes = read_mesh(obj, {.max_file_bytes = 10});
  REQUIRE_FALSE(bytes.ok());
  CHECK_THAT(bytes.error().message, Contains("larger than the limit of 10 bytes per mesh file"));
}

TEST_CASE("mesh_io: a NaN coordinate is refused by the reader, and by validation in memory", "[mesh_io]") {
  const std::filesystem::path path = write_temp("nan.off", "OFF\n4 4 0\n0 0 0\n1 0 0\nnan 1 0\n0 0 inf\n"
                                                           "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  CHECK_THAT(read_error(path), StartsWith(path.string() + ":5: ") && Contains("non-finite number 'nan'"));
  Mesh mesh = make_box(Vec3(1, 1, 1));
  mesh.vertices[2].x() = std::numeric_limits<double>::quiet_NaN();
  CHECK_FALSE(all_finite(mesh));
  const Result<ValidationReport> report = validate_solid(mesh, "nan.off");
  REQUIRE_FALSE(report.ok());
  CHECK_THAT(report.error().message, StartsWith("nan.off: vertex 2 has a non-finite coordinate"));
}

TEST_CASE("mesh_io: malformed OBJ files give errors naming the file", "[mesh_io]") {
  const std::filesystem::path range = write_temp("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  CHECK_THAT(read_error(range), StartsWith(range.string() + ":4: ") && Contains("out of"));
  const std::filesystem::path negative = write_temp("negative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -7\n");
  CHECK_THAT(read_error(negative), StartsWith(negative.string() + ":4: "));
  CHECK_THAT(read_error(temp_file("does_not_exist.obj")), Contains("cannot open"));
  const Result<Mesh> quad = read_obj(write_temp("quad.obj", "v 0 0 0\nv 2 0 0\nv 2 3 0\nv 0 3 0\nf 1 2 3 4\n"));
  REQUIRE(quad.ok());
  CHECK(quad->triangle_count() == 2);
  CHECK(surface_area(*quad) == Approx(6.0));
}

TEST_CASE("mesh_io: writing to an impossible path is an error", "[mesh_io]") {
  const std::filesystem::path path = temp_file("no_such_dir") / "mesh.obj";
  const Mesh box = make_box(Vec3(1, 1, 1));
  CHECK_THAT(write_obj(box, path).error().message, StartsWith(path.string() + ": "));
  CHECK_THAT(write_off(box, path).error().message, StartsWith(path.string() + ": "));
}

TEST_CASE("mesh_io: a real OFF file cut in half is reported as truncated", "[mesh_io][real]") {
  if (!test::have_meshes()) return;
  std::ifstream in(test::mesh_dir() / "elephant.off", std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string whole = text.str();
  REQUIRE(whole.size() > 1000);
  const std::filesystem::path half = write_temp("elephant_half.off", whole.substr(0, whole.rfind('\n', whole.size() / 2) + 1));
  CHECK_THAT(read_error(half), StartsWith(half.string() + ":") && Contains("truncated file"));
}

TEST_CASE("mesh_io: every real OFF file reads or fails cleanly", "[mesh_io][real][slow]") {
  if (!test::have_meshes()) return;
  int read = 0, valid = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::mesh_dir())) {
    if (entry.path().extension() != ".off") continue;
    INFO(entry.path().string());
    Result<Mesh> mesh = read_off(entry.path());
    if (!mesh.ok()) {
      CHECK_THAT(mesh.error().message, StartsWith(entry.path().string() + ":"));
      continue;
    }
    ++read;
    const std::string name = entry.path().filename().string();
    const Result<ValidationReport> report = validate_solid(*mesh, name);
    if (report.ok()) {
      ++valid;
      CHECK(is_closed_and_oriented(*mesh));
      CHECK(signed_volume(*mesh) > 0.0);
    } else {
      CHECK_THAT(report.error().message, StartsWith(name + ": "));
    }
  }
  CHECK(read > 0);
  CHECK(valid > 0);
}
