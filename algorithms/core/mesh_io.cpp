#include "algorithms/core/mesh_io.h"

#include "algorithms/core/bounded_read.h"
#include "algorithms/core/material_library.h"
#include "algorithms/core/mesh_text.h"
#include "algorithms/core/polygon_triangulation.h"

#include <algorithm>
#include <cassert>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string_view>
#include <vector>

namespace shatter {
namespace {

/// The numbers a vertex line of an OFF variant holds: x y z, then [nx ny nz] for N, [r g b] or
/// [r g b a] for C, [s t] for ST (Geomview's order). Two counts when colours are allowed.
struct OffVertexLayout {
  std::size_t plain = 3;          ///< numbers without colour, or with an RGB colour (`C`)
  std::size_t with_alpha = 3;     ///< numbers with an RGBA colour (`C`); equal to `plain` otherwise
};

/// The layout of an OFF keyword (OFF, COFF, NOFF, STOFF, ... in Geomview's prefix order), or
/// nothing when it is not one.
std::optional<OffVertexLayout> off_layout(std::string_view s) {
  std::size_t extra = 0;
  bool colour = false;
  if (s.starts_with("ST")) s.remove_prefix(2), extra += 2;
  if (s.starts_with("C")) s.remove_prefix(1), colour = true;
  if (s.starts_with("N")) s.remove_prefix(1), extra += 3;
  if (s != "OFF") return std::nullopt;
  OffVertexLayout layout;
  layout.plain = 3 + extra + (colour ? 3 : 0);
  layout.with_alpha = 3 + extra + (colour ? 4 : 0);
  return layout;
}

void append_vertex(std::string& out, const char* prefix, const Vec3& p) {
  char buffer[96];
  const int n = std::snprintf(buffer, sizeof buffer, "%s%.17g %.17g %.17g\n", prefix, p.x(), p.y(), p.z());
  out.append(buffer, static_cast<std::size_t>(n));
}

void append_face(std::string& out, const char* prefix, const Triangle& t, int base) {
  char buffer[64];
  const int n = std::snprintf(buffer, sizeof buffer, "%s%d %d %d\n", prefix, t[0] + base, t[1] + base, t[2] + base);
  out.append(buffer, static_cast<std::size_t>(n));
}

/// Appends a face `f a/t/n b/t/n c/t/n`, each of `uv` and `normal` given as the first 1-based index
/// of the triangle's three consecutive corner entries (0: the channel is absent).
void append_attributed_face(std::string& out, const Triangle& t, std::size_t uv, std::size_t normal) {
  char buffer[192];
  out += "f";
  for (int k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(k);
    int n = 0;
    if (uv != 0 && normal != 0)
      n = std::snprintf(buffer, sizeof buffer, " %d/%zu/%zu", t[i] + 1, uv + i, normal + i);
    else if (uv != 0)
      n = std::snprintf(buffer, sizeof buffer, " %d/%zu", t[i] + 1, uv + i);
    else if (normal != 0)
      n = std::snprintf(buffer, sizeof buffer, " %d//%zu", t[i] + 1, normal + i);
    else
      n = std::snprintf(buffer, sizeof buffer, " %d", t[i] + 1);
    out.append(buffer, static_cast<std::size_t>(n));
  }
  out += "\n";
}

/// The attributed OBJ text (see write_obj): per-corner vn and vt, usemtl per run of one material.
std::string attributed_obj_text(const Mesh& mesh, const std::string& mtl_file) {
  const MeshAttributes& attr = mesh.attributes;
  const AttributeLayout& layout = attr.layout;
  std::string out = "# shatterbench mesh\n";
  if (!attr.slots.empty()) out += "mtllib " + mtl_file + "\n";
  for (const Vec3& p : mesh.vertices) append_vertex(out, "v ", p);
  char buffer[96];
  if (layout.normals)
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        const double* c = attr.corner(f, k) + AttributeLayout::normal_offset();
        Vec3 n(c[0], c[1], c[2]);
        if (n.norm() > 0.0) n.normalize();
        append_vertex(out, "vn ", n);
      }
  if (layout.uv_sets > 0)
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        const double* c = attr.corner(f, k) + layout.uv_offset(0);
        const int n = std::snprintf(buffer, sizeof buffer, "vt %.17g %.17g\n", c[0], c[1]);
        out.append(buffer, static_cast<std::size_t>(n));
      }
  for (const FaceTag tag : {FaceTag::surface, FaceTag::cut, FaceTag::repair}) {
    if (std::find(mesh.tags.begin(), mesh.tags.end(), tag) == mesh.tags.end()) continue;
    out += tag == FaceTag::cut ? "g cut\n" : tag == FaceTag::repair ? "g repair\n" : "g surface\n";
    std::int32_t material = -1;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      if (mesh.tags[f] != tag) continue;
      if (!attr.materials.empty() && attr.materials[f] != material && attr.materials[f] >= 0 &&
          attr.materials[f] < static_cast<std::int32_t>(attr.slots.size())) {
        material = attr.materials[f];
        out += "usemtl " + attr.slots[static_cast<std::size_t>(material)].name + "\n";
      }
      const std::size_t first = 3 * f + 1;
      append_attributed_face(out, mesh.triangles[f], layout.uv_sets > 0 ? first : 0, layout.normals ? first : 0);
    }
  }
  return out;
}

}  // namespace

Result<Mesh> read_off(const std::filesystem::path& path, const MeshReadLimits& limits) {
  Result<std::string> text = read_file_bounded(path, limits.max_file_bytes, "mesh file");
  if (!text) return text.error();
  const std::string file = path.string();
  TokenLines lines(*text);
  auto fail = [&](const std::string& what) { return Error{file + ":" + std::to_string(lines.line()) + ": " + what}; };

  if (!lines.next()) return fail("empty file, expected header 'OFF'");
  const std::string keyword(lines.tokens()[0].substr(0, 40));
  const std::optional<OffVertexLayout> layout = off_layout(lines.tokens()[0]);
  if (!layout) return fail("expected header 'OFF', found '" + keyword + "'");
  std::size_t first = 1;  // the counts may follow the keyword on the same line
  if (lines.tokens().size() == 1) {
    if (!lines.next()) return fail("truncated file: missing vertex and face counts");
    first = 0;
  }
  const auto& header = lines.tokens();
  if (header[first] == "BINARY") return fail("binary OFF is not supported");
  if (header.size() - first < 2) return fail("expected vertex and face counts");
  if (header.size() - first > 3) return fail("expected vertex, face and edge counts, found more numbers");
  std::int64_t counts[3] = {0, 0, 0};
  for (std::size_t i = 0; first + i < header.size(); ++i) {
    const Result<std::int64_t> c = parse_integer(header[first + i]);
    if (!c) return fail(c.error().message + " as a count");
    if (*c < 0) return fail("negative count " + std::to_string(*c));
    counts[i] = *c;
  }
  const std::int64_t vertex_count = counts[0], face_count = counts[1];
  // Before anything is reserved: every face is at least one triangle.
  if (vertex_count > limits.max_vertices)
    return fail("vertex count " + std::to_string(vertex_count) + " exceeds the limit of " +
                std::to_string(limits.max_vertices) + " vertices per mesh");
  if (face_count > limits.max_triangles)
    return fail("face count " + std::to_string(face_count) + " exceeds the limit of " +
                std::to_string(limits.max_triangles) + " triangles per mesh");

  // Reserve no more than the file can hold (a vertex line takes at least 6 bytes, a face line 8),
  // so that a small file claiming huge counts fails on truncation without a large allocation.
  Mesh mesh;
  mesh.vertices.reserve(std::min(static_cast<std::size_t>(vertex_count), text->size() / 6));
  for (std::int64_t v = 0; v < vertex_count; ++v) {
    if (!lines.next())
      return fail("truncated file: expected " + std::to_string(vertex_count) + " vertices, found " + std::to_string(v));
    const auto& tokens = lines.tokens();
    const auto vertex = [v] { return "vertex " + std::to_string(v); };  // built only for a message
    if (tokens.size() != layout->plain && tokens.size() != layout->with_alpha)
      return fail(vertex() + " has " + std::to_string(tokens.size()) + " numbers, expected " +
                  std::to_string(layout->plain) +
                  (layout->with_alpha != layout->plain ? " or " + std::to_string(layout->with_alpha) : std::string()) +
                  " for header '" + keyword + "'");
    Vec3 p;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
      const Result<double> x = parse_finite_double(tokens[i]);
      if (!x) return fail(vertex() + ": " + x.error().message);
      if (i < 3) p[static_cast<int>(i)] = *x;  // normals, colours and texture coordinates are checked, not kept
    }
    mesh.vertices.push_back(p);
  }

  mesh.triangles.reserve(std::min(static_cast<std::size_t>(face_count), text->size() / 8));
  std::vector<std::int32_t> poly;
  for (std::int64_t f = 0; f < face_count; ++f) {
    if (!lines.next())
      return fail("truncated file: expected " + std::to_string(face_count) + " faces, found " + std::to_string(f));
    const auto& tokens = lines.tokens();
    const auto face = [f] { return "face " + std::to_string(f); };  // built only for a message
    const Result<std::int64_t> n = parse_integer(tokens[0]);
    if (!n) return fail(face() + ": " + n.error().message + " as corner count");
    if (*n < 3) return fail(face() + " has " + std::to_string(*n) + " corners (at least 3 needed)");
    if (*n > kMaxPolygonCorners)
      return fail(face() + " has " + std::to_string(*n) + " corners, past the limit of " +
                  std::to_string(kMaxPolygonCorners) + " corners per polygon");
    const auto listed = static_cast<std::int64_t>(tokens.size()) - 1;
    if (listed < *n)
      return fail(face() + " declares " + std::to_string(*n) + " corners but lists " + std::to_string(listed));
    if (listed - *n > 4)
      return fail(face() + " has " + std::to_string(listed - *n) + " numbers after its " + std::to_string(*n) +
                  " corners (a colour has at most 4)");
    for (std::int64_t i = *n + 1; i <= listed; ++i)
      if (const Result<double> c = parse_finite_double(tokens[static_cast<std::size_t>(i)]); !c)
        return fail(face() + ": " + c.error().message + " in its colour");
    if (static_cast<std::int64_t>(mesh.triangles.size()) + *n - 2 > limits.max_triangles)
      return fail(face() + ": triangle count (after triangulation) exceeds the limit of " +
                  std::to_string(limits.max_triangles) + " triangles per mesh");
    poly.clear();
    for (std::int64_t i = 1; i <= *n; ++i) {
      const Result<std::int64_t> index = parse_integer(tokens[static_cast<std::size_t>(i)]);
      if (!index) return fail(face() + ": " + index.error().message);
      if (*index < 0 || *index >= vertex_count)
        return fail(face() + ": vertex index " + std::to_string(*index) + " out of range (" +
                    std::to_string(vertex_count) + " vertices)");
      poly.push_back(static_cast<std::int32_t>(*index));
    }
    if (Status s = triangulate_polygon(mesh.vertices, poly, mesh.triangles); !s)
      return fail(face() + ": " + s.error().message);
  }
  if (lines.next())
    return fail("count mismatch: data after the " + std::to_string(vertex_count) + " vertices and " +
                std::to_string(face_count) + " faces declared in the header");
  mesh.tags.assign(mesh.triangles.size(), FaceTag::surface);
  return mesh;
}

Result<Mesh> read_mesh(const std::filesystem::path& path, const MeshReadLimits& limits) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".off") return read_off(path, limits);
  if (ext == ".obj") return read_obj(path, limits);
  return Error{path.string() + ": unknown mesh format '" + ext + "' (expected .off or .obj)"};
}

Status write_obj(const Mesh& mesh, const std::filesystem::path& path, const std::string& mtl_file) {
  assert(mesh.tags.size() == mesh.triangles.size());
  if (!mesh.attributes.empty()) {
    std::string library = mtl_file;
    if (!mesh.attributes.slots.empty() && library.empty()) {
      library = path.stem().string() + ".mtl";
      if (Status s = write_mtl(mesh.attributes.slots, path.parent_path() / library); !s) return s;
    }
    return write_file_bytes(attributed_obj_text(mesh, library), path);
  }
  std::string out = "# shatterbench mesh\n";
  out.reserve(mesh.vertices.size() * 60 + mesh.triangles.size() * 24);
  for (const Vec3& p : mesh.vertices) append_vertex(out, "v ", p);
  for (const FaceTag tag : {FaceTag::surface, FaceTag::cut, FaceTag::repair}) {
    if (std::find(mesh.tags.begin(), mesh.tags.end(), tag) == mesh.tags.end()) continue;
    out += tag == FaceTag::cut ? "g cut\n" : tag == FaceTag::repair ? "g repair\n" : "g surface\n";
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
      if (mesh.tags[f] == tag) append_face(out, "f ", mesh.triangles[f], 1);
  }
  return write_file_bytes(out, path);
}

Status write_off(const Mesh& mesh, const std::filesystem::path& path) {
  std::string out = "OFF\n" + std::to_string(mesh.vertices.size()) + " " + std::to_string(mesh.triangles.size()) + " 0\n";
  out.reserve(mesh.vertices.size() * 60 + mesh.triangles.size() * 24);
  for (const Vec3& p : mesh.vertices) append_vertex(out, "", p);
  for (const Triangle& t : mesh.triangles) append_face(out, "3 ", t, 0);
  return write_file_bytes(out, path);
}

}  // namespace shatter
