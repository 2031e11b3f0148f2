#include "harness/cases/case_mesh.h"

#include "harness/cases/physical_range.h"
#include "harness/cases/isolated_import.h"
#include "harness/cases/prism_mesh.h"

#include "algorithms/assets/read_asset.h"
#include "algorithms/core/mesh_limits.h"
#include "algorithms/core/primitives.h"
#include "harness/limits.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

namespace shatter {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

/// Reads `segments`-like counts: an integer in [min, kMaxPrimitiveSegments].
void read_count(JsonReader& r, const json& obj, std::string_view path, std::string_view key, int min, int& out) {
  if (r.read(obj, path, key, out)) {
    const std::string at = key_path(path, key);
    r.at_least(at, out, min) && r.at_most(at, out, kMaxPrimitiveSegments);
  }
}

/// Refuses a primitive whose two counts make more than kMaxMeshTriangles triangles.
void check_triangles(JsonReader& r, std::string_view path, std::string_view counts, std::int64_t triangles) {
  if (!r.failed() && triangles > kMaxMeshTriangles)
    r.fail(path, fmt::format("{} make {} triangles, which exceeds the limit of {} triangles per mesh", counts,
                             triangles, kMaxMeshTriangles));
}

/// Reads a required length (m, > 0).
void read_length(JsonReader& r, const json& obj, std::string_view path, std::string_view key, double& out) {
  read_required_in_range(r, obj, path, key, out, kLengthRange);
}

BoxSpec read_box(JsonReader& r, const json& v, std::string_view path) {
  BoxSpec s;
  if (!r.object(v, path, {"size", "center"})) return s;
  read_required_in_range(r, v, path, "size", s.size, kLengthRange);
  read_in_range(r, v, path, "center", s.center, kCoordinateRange);
  return s;
}

SphereSpec read_sphere(JsonReader& r, const json& v, std::string_view path) {
  SphereSpec s;
  if (!r.object(v, path, {"radius", "center", "segments", "rings"})) return s;
  read_length(r, v, path, "radius", s.radius);
  read_in_range(r, v, path, "center", s.center, kCoordinateRange);
  read_count(r, v, path, "segments", 3, s.segments);
  read_count(r, v, path, "rings", 2, s.rings);
  check_triangles(r, path, fmt::format("segments x rings = {} x {}", s.segments, s.rings),
                  2 * std::int64_t{s.segments} * (s.rings - 1));
  return s;
}

CylinderSpec read_cylinder(JsonReader& r, const json& v, std::string_view path) {
  CylinderSpec s;
  if (!r.object(v, path, {"radius", "height", "center", "segments"})) return s;
  read_length(r, v, path, "radius", s.radius);
  read_length(r, v, path, "height", s.height);
  read_in_range(r, v, path, "center", s.center, kCoordinateRange);
  read_count(r, v, path, "segments", 3, s.segments);
  return s;
}

TorusSpec read_torus(JsonReader& r, const json& v, std::string_view path) {
  TorusSpec s;
  if (!r.object(v, path, {"major_radius", "minor_radius", "center", "major_segments", "minor_segments"})) return s;
  read_length(r, v, path, "major_radius", s.major_radius);
  read_length(r, v, path, "minor_radius", s.minor_radius);
  if (!r.failed() && s.minor_radius >= s.major_radius)
    r.fail(key_path(path, "minor_radius"),
           fmt::format("must be < major_radius ({}), got {}", s.major_radius, s.minor_radius));
  read_in_range(r, v, path, "center", s.center, kCoordinateRange);
  read_count(r, v, path, "major_segments", 3, s.major_segments);
  read_count(r, v, path, "minor_segments", 3, s.minor_segments);
  check_triangles(r, path, fmt::format("major_segments x minor_segments = {} x {}", s.major_segments, s.minor_segments),
                  2 * std::int64_t{s.major_segments} * s.minor_segments);
  return s;
}

TubeSpec read_tube(JsonReader& r, const json& v, std::string_view path) {
  TubeSpec s;
  if (!r.object(v, path, {"inner_radius", "outer_radius", "height", "center", "segments"})) return s;
  read_length(r, v, path, "inner_radius", s.inner_radius);
  read_length(r, v, path, "outer_radius", s.outer_radius);
  if (!r.failed() && s.inner_radius >= s.outer_radius)
    r.fail(key_path(path, "inner_radius"),
           fmt::format("must be < outer_radius ({}), got {}", s.outer_radius, s.inner_radius));
  read_length(r, v, path, "height", s.height);
  read_in_range(r, v, path, "center", s.center, kCoordinateRange);
  read_count(r, v, path, "segments", 3, s.segments);
  return s;
}

/// True when read_asset reads `file` by its extension (.off, .obj, .glb, .fbx, ..., any case).
bool has_mesh_extension(const fs::path& file) { return is_asset_extension(file.extension().string()); }

/// Reads `{"file", "scale", "rotate", "translate", "repair"}` and resolves the file.
MeshFileSpec read_file_spec(JsonReader& r, const json& v, std::string_view path, const fs::path& case_dir) {
  MeshFileSpec s;
  const std::string file_at = key_path(path, "file");
  if (!r.read_required(v, path, "file", s.file)) return s;
  const fs::path file(s.file);
  if (s.file.empty() || !has_mesh_extension(file)) {
    r.fail(file_at, fmt::format("expected a mesh file (.off, .obj, .gltf, .glb, .fbx, .ply, .stl, .dae, .3ds, ...), got \"{}\"",
                                s.file));
    return s;
  }
  std::error_code ec;
  if (file.is_absolute()) {
    s.path = file;
  } else if (fs::is_regular_file(case_dir / file, ec)) {
    s.path = case_dir / file;
  } else {
    s.path = file;  // relative to the current directory
  }
  if (!fs::is_regular_file(s.path, ec)) {
    std::string where;
    if (!file.is_absolute())
      where = case_dir.empty() ? " (looked in the current directory)"
                               : fmt::format(" (looked in \"{}\" and the current directory)", case_dir.string());
    r.fail(file_at, fmt::format("mesh file \"{}\" not found{}", s.file, where));
    return s;
  }
  read_in_range(r, v, path, "scale", s.scale, kScaleRange);
  r.read(v, path, "rotate", s.rotate_deg);
  read_in_range(r, v, path, "translate", s.translate, kCoordinateRange);
  r.read(v, path, "repair", s.repair);
  return s;
}

/// cos and sin of `degrees`, exact at multiples of 90.
std::pair<double, double> cos_sin_deg(double degrees) {
  const double turns = std::fmod(degrees, 360.0);
  if (std::fmod(turns, 90.0) == 0.0) {
    const int quarter = static_cast<int>(std::lround(turns / 90.0) % 4 + 4) % 4;
    constexpr double c[] = {1.0, 0.0, -1.0, 0.0};
    constexpr double s[] = {0.0, 1.0, 0.0, -1.0};
    return {c[quarter], s[quarter]};
  }
  const double a = degrees * std::numbers::pi / 180.0;
  return {std::cos(a), std::sin(a)};
}

}  // namespace

MeshSpec read_mesh_spec(JsonReader& r, const json& value, std::string_view path, const fs::path& case_dir) {
  if (!r.object(value, path, {"box", "sphere", "cylinder", "torus", "tube", "prism", "file", "scale", "rotate", "translate", "repair"}))
    return {};
  const char* primitives[] = {"box", "sphere", "cylinder", "torus", "tube", "prism", "file"};
  std::vector<std::string_view> given;
  for (const char* key : primitives)
    if (value.contains(key)) given.emplace_back(key);
  if (given.size() != 1) {
    r.fail(path, given.empty() ? "expected one of box, sphere, cylinder, torus, tube, prism, file"
                               : fmt::format("\"{}\" and \"{}\" are exclusive: give one", given[0], given[1]));
    return {};
  }
  const std::string_view kind = given[0];
  if (kind != "file") {
    for (const char* key : {"scale", "rotate", "translate", "repair"})
      if (value.contains(key)) {
        r.fail(key_path(path, key), "only allowed with \"file\" (a primitive has \"center\")");
        return {};
      }
  }
  const std::string at = key_path(path, kind);
  const json& v = value.at(kind);
  if (kind == "box") return read_box(r, v, at);
  if (kind == "sphere") return read_sphere(r, v, at);
  if (kind == "cylinder") return read_cylinder(r, v, at);
  if (kind == "torus") return read_torus(r, v, at);
  if (kind == "tube") return read_tube(r, v, at);
  if (kind == "prism") return read_prism(r, v, at);
  return read_file_spec(r, value, path, case_dir);
}

Eigen::Matrix3d rotation_xyz_deg(const Vec3& degrees) {
  const auto [cx, sx] = cos_sin_deg(degrees.x());
  const auto [cy, sy] = cos_sin_deg(degrees.y());
  const auto [cz, sz] = cos_sin_deg(degrees.z());
  Eigen::Matrix3d rx, ry, rz;
  rx << 1, 0, 0, 0, cx, -sx, 0, sx, cx;
  ry << cy, 0, sy, 0, 1, 0, -sy, 0, cy;
  rz << cz, -sz, 0, sz, cz, 0, 0, 0, 1;
  return rz * ry * rx;  // x first
}

Result<Mesh> build_case_mesh(const MeshSpec& spec, const std::string& what) {
  if (const auto* s = std::get_if<BoxSpec>(&spec)) return make_box(s->size, s->center);
  if (const auto* s = std::get_if<SphereSpec>(&spec)) return make_sphere(s->radius, s->segments, s->rings, s->center);
  if (const auto* s = std::get_if<CylinderSpec>(&spec))
    return make_cylinder(s->radius, s->height, s->segments, s->center);
  if (const auto* s = std::get_if<TorusSpec>(&spec))
    return make_torus(s->major_radius, s->minor_radius, s->major_segments, s->minor_segments, s->center);
  if (const auto* s = std::get_if<TubeSpec>(&spec))
    return make_tube(s->inner_radius, s->outer_radius, s->height, s->segments, s->center);
  if (const auto* s = std::get_if<PrismSpec>(&spec)) return make_prism(*s, what);
  const auto& file = std::get<MeshFileSpec>(spec);
  Result<Mesh> mesh = read_asset_isolated(file.path);
  if (!mesh) return Error{fmt::format("{}: {}", what, mesh.error().message)};
  const Eigen::Matrix3d rotation = rotation_xyz_deg(file.rotate_deg);
  const bool identity =
      file.scale == 1.0 && rotation == Eigen::Matrix3d::Identity() && (file.translate.array() == 0.0).all();
  if (!identity)
    for (Vec3& p : mesh->vertices) p = rotation * (file.scale * p) + file.translate;
  // Normals and tangents turn with the mesh (a positive uniform scale leaves their directions).
  MeshAttributes& a = mesh->attributes;
  if (rotation != Eigen::Matrix3d::Identity() && (a.layout.normals || a.layout.tangents)) {
    const auto stride = static_cast<std::size_t>(a.layout.stride());
    for (std::size_t at = 0; at < a.corners.size(); at += stride) {
      double* c = a.corners.data() + at;
      if (a.layout.normals) {
        Eigen::Map<Vec3> normal(c + AttributeLayout::normal_offset());
        normal = (rotation * normal).eval();
      }
      if (a.layout.tangents) {
        Eigen::Map<Vec3> tangent(c + a.layout.tangent_offset());
        tangent = (rotation * tangent).eval();
      }
    }
  }
  return mesh;
}

}  // namespace shatter
