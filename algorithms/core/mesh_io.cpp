#include "algorithms/core/mesh_io.h"

#include <Eigen/Geometry>
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <span>
#include <sstream>
#include <string_view>
#include <vector>

namespace shatter {
namespace {

std::string file_limit_error(const std::filesystem::path& path, std::uint64_t limit) {
  return path.string() + ": larger than the limit of " + std::to_string(limit) + " bytes per mesh file";
}

/// The whole file, refused when it is larger than `max_bytes`: checked on its size first (nothing is
/// read then), and again while reading (a pipe or a growing file has no size to trust).
Result<std::string> read_text(const std::filesystem::path& path, std::uint64_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{path.string() + ": cannot open file"};
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size > max_bytes)
    return Error{file_limit_error(path, max_bytes) + " (the file has " + std::to_string(size) + ")"};
  std::string text;
  if (!ec) text.reserve(static_cast<std::size_t>(size));
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    const auto n = static_cast<std::size_t>(in.gcount());
    if (text.size() + n > max_bytes) return Error{file_limit_error(path, max_bytes)};
    text.append(buffer, n);
  }
  if (in.bad()) return Error{path.string() + ": read error"};
  return text;
}

/// Iterates over the non-empty lines of a text, with '#' comments stripped and tokens split.
class TokenLines {
 public:
  explicit TokenLines(std::string_view text) : text_(text) {}
  /// Moves to the next line with at least one token; false at the end of the text.
  bool next() {
    while (pos_ < text_.size()) {
      std::size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view line = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++line_;
      if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
      tokens_.clear();
      std::size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) tokens_.push_back(line.substr(start, i - start));
      }
      if (!tokens_.empty()) return true;
    }
    tokens_.clear();
    return false;
  }
  /// 1-based number of the current line (the last line at the end of the text).
  [[nodiscard]] int line() const { return line_; }
  /// Tokens of the current line.
  [[nodiscard]] const std::vector<std::string_view>& tokens() const { return tokens_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 0;
  std::vector<std::string_view> tokens_;
};

/// A double token; "nan" and "inf" parse (validation rejects them later, by vertex index).
std::optional<double> parse_double(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (end != s.data() + s.size()) return std::nullopt;
  if (ec == std::errc::result_out_of_range) return std::strtod(std::string(s).c_str(), nullptr);
  if (ec != std::errc{}) return std::nullopt;
  return value;
}

std::optional<std::int64_t> parse_integer(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc{} || end != s.data() + s.size()) return std::nullopt;
  return value;
}

/// OFF, with the optional ST/C/N prefixes whose extra per-vertex values are ignored.
bool is_off_keyword(std::string_view s) {
  if (s.starts_with("ST")) s.remove_prefix(2);
  if (s.starts_with("C")) s.remove_prefix(1);
  if (s.starts_with("N")) s.remove_prefix(1);
  return s == "OFF";
}

/// Twice the signed area of (a, b, c) in the projection.
double cross2(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

/// Triangulates one polygon (vertex indices into `vertices`) keeping its winding: a fan when every
/// corner is strictly convex, ear clipping otherwise. False when the polygon is too large to clip.
bool triangulate_polygon(const std::vector<Vec3>& vertices, std::span<const std::int32_t> poly,
                         std::vector<Triangle>& out) {
  const std::size_t m = poly.size();
  const Vec3& origin = vertices[poly[0]];
  Vec3 normal = Vec3::Zero();  // Newell: twice the vector area
  for (std::size_t i = 0; i < m; ++i)
    normal += (vertices[poly[i]] - origin).cross(vertices[poly[(i + 1) % m]] - origin);
  int axis = 0;
  normal.cwiseAbs().maxCoeff(&axis);
  // Project by dropping the dominant axis, keeping the cyclic order so that a corner turning like
  // the polygon has the sign of normal[axis].
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  const double sign = normal[axis] >= 0.0 ? 1.0 : -1.0;
  std::vector<Vec2> pts(m);
  for (std::size_t i = 0; i < m; ++i) pts[i] = Vec2(vertices[poly[i]][u], vertices[poly[i]][w]);

  bool convex = normal[axis] != 0.0 && std::isfinite(normal[axis]);
  for (std::size_t i = 0; convex && i < m; ++i)
    convex = sign * cross2(pts[(i + m - 1) % m], pts[i], pts[(i + 1) % m]) > 0.0;
  if (convex || normal[axis] == 0.0 || !std::isfinite(normal[axis])) {
    for (std::size_t i = 1; i + 1 < m; ++i) out.push_back({poly[0], poly[i], poly[i + 1]});
    return true;
  }
  if (static_cast<std::int64_t>(m) > kMaxEarClippingCorners) return false;

  std::vector<std::size_t> ring(m);
  for (std::size_t i = 0; i < m; ++i) ring[i] = i;
  std::size_t k = 0;
  while (ring.size() > 3) {
    const std::size_t n = ring.size();
    bool clipped = false;
    for (std::size_t tries = 0; tries < n && !clipped; ++tries, k = (k + 1) % n) {
      const std::size_t ip = ring[(k + n - 1) % n], ic = ring[k], in = ring[(k + 1) % n];
      const Vec2 &a = pts[ip], &b = pts[ic], &c = pts[in];
      if (sign * cross2(a, b, c) <= 0.0) continue;
      bool empty = true;
      for (std::size_t j = 0; j < n && empty; ++j) {
        const Vec2& p = pts[ring[j]];
        if (p == a || p == b || p == c) continue;  // the corners themselves, or copies of them
        empty = !(sign * cross2(a, b, p) >= 0.0 && sign * cross2(b, c, p) >= 0.0 && sign * cross2(c, a, p) >= 0.0);
      }
      if (!empty) continue;
      out.push_back({poly[ip], poly[ic], poly[in]});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(k));
      clipped = true;
      k = k % ring.size();
      break;
    }
    if (!clipped) {  // no clean ear (self-touching or collinear polygon): cut one corner to finish
      const std::size_t ip = ring[(k + n - 1) % n], ic = ring[k], in = ring[(k + 1) % n];
      out.push_back({poly[ip], poly[ic], poly[in]});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(k));
      k = k % ring.size();
    }
  }
  out.push_back({poly[ring[0]], poly[ring[1]], poly[ring[2]]});
  return true;
}

/// Ignores material libraries: only positions and faces are read.
class NoMaterials : public tinyobj::MaterialReader {
 public:
  bool operator()(const std::string&, std::vector<tinyobj::material_t>*, std::map<std::string, int>*,
                  std::string*, std::string*) override {
    return true;
  }
};

/// The `v` positions of an OBJ text, correctly rounded. tinyobjloader parses numbers by hand into
/// its real_t (float in Debian's default build), so its positions can be off by up to one float ulp;
/// an empty or short result (a malformed `v` line) means "use tinyobjloader's values".
std::vector<Vec3> exact_obj_positions(std::string_view text) {
  std::vector<Vec3> positions;
  TokenLines lines(text);
  while (lines.next()) {
    const auto& tokens = lines.tokens();
    if (tokens[0] != "v") continue;
    if (tokens.size() < 4) return {};
    Vec3 p;
    for (int i = 0; i < 3; ++i) {
      const std::optional<double> x = parse_double(tokens[i + 1]);
      if (!x) return {};
      p[i] = *x;
    }
    positions.push_back(p);
  }
  return positions;
}

/// Refuses an OBJ text whose `v` statements or whose `f` statements' triangles (k corners make k - 2)
/// pass the limits, naming the first line past it; run before the text is parsed.
Status check_obj_counts(std::string_view text, const std::string& file, const MeshReadLimits& limits) {
  std::int64_t vertices = 0, triangles = 0;
  TokenLines lines(text);
  while (lines.next()) {
    const auto& tokens = lines.tokens();
    const auto at = [&] { return file + ":" + std::to_string(lines.line()) + ": "; };
    if (tokens[0] == "v" && ++vertices > limits.max_vertices)
      return Error{at() + "vertex count exceeds the limit of " + std::to_string(limits.max_vertices) +
                   " vertices per mesh"};
    if (tokens[0] == "f" && tokens.size() > 3) {
      triangles += static_cast<std::int64_t>(tokens.size()) - 3;
      if (triangles > limits.max_triangles)
        return Error{at() + "triangle count (after triangulation) exceeds the limit of " +
                     std::to_string(limits.max_triangles) + " triangles per mesh"};
    }
  }
  return {};
}

std::string first_line(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  while (!line.empty() && (line.back() == '.' || std::isspace(static_cast<unsigned char>(line.back()))))
    line.pop_back();
  return line;
}

Status write_text(const std::string& text, const std::filesystem::path& path) {
  std::FILE* file = std::fopen(path.string().c_str(), "wb");
  if (file == nullptr) return Error{path.string() + ": cannot write: " + std::strerror(errno)};
  const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed) return Error{path.string() + ": write failed: " + std::strerror(errno)};
  return {};
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

}  // namespace

Result<Mesh> read_off(const std::filesystem::path& path, const MeshReadLimits& limits) {
  Result<std::string> text = read_text(path, limits.max_file_bytes);
  if (!text) return text.error();
  const std::string file = path.string();
  TokenLines lines(*text);
  auto fail = [&](std::string what) { return Error{file + ":" + std::to_string(lines.line()) + ": " + what}; };

  if (!lines.next()) return fail("empty file, expected header 'OFF'");
  if (!is_off_keyword(lines.tokens()[0]))
    return fail("expected header 'OFF', found '" + std::string(lines.tokens()[0]) + "'");
  std::size_t first = 1;  // the counts may follow the keyword on the same line
  if (lines.tokens().size() == 1) {
    if (!lines.next()) return fail("truncated file: missing vertex and face counts");
    first = 0;
  }
  const auto& header = lines.tokens();
  if (header[first] == "BINARY") return fail("binary OFF is not supported");
  if (header.size() - first < 2) return fail("expected vertex and face counts");
  std::int64_t counts[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    const std::optional<std::int64_t> c = parse_integer(header[first + i]);
    if (!c) return fail("non-numeric count '" + std::string(header[first + i]) + "'");
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
    if (tokens.size() < 3) return fail("vertex " + std::to_string(v) + " has fewer than 3 coordinates");
    Vec3 p;
    for (int i = 0; i < 3; ++i) {
      const std::optional<double> x = parse_double(tokens[i]);
      if (!x) return fail("non-numeric token '" + std::string(tokens[i]) + "' in vertex " + std::to_string(v));
      p[i] = *x;
    }
    mesh.vertices.push_back(p);  // further values on the line (colours, normals) are ignored
  }

  mesh.triangles.reserve(std::min(static_cast<std::size_t>(face_count), text->size() / 8));
  std::vector<std::int32_t> poly;
  for (std::int64_t f = 0; f < face_count; ++f) {
    if (!lines.next())
      return fail("truncated file: expected " + std::to_string(face_count) + " faces, found " + std::to_string(f));
    const auto& tokens = lines.tokens();
    const std::string face = "face " + std::to_string(f);
    const std::optional<std::int64_t> n = parse_integer(tokens[0]);
    if (!n) return fail("non-numeric token '" + std::string(tokens[0]) + "' as corner count of " + face);
    if (*n < 3) return fail(face + " has " + std::to_string(*n) + " corners (at least 3 needed)");
    if (static_cast<std::int64_t>(tokens.size()) - 1 < *n)
      return fail(face + " declares " + std::to_string(*n) + " corners but lists " + std::to_string(tokens.size() - 1));
    poly.clear();
    for (std::int64_t i = 1; i <= *n; ++i) {
      const std::optional<std::int64_t> index = parse_integer(tokens[i]);
      if (!index) return fail("non-numeric token '" + std::string(tokens[i]) + "' in " + face);
      if (*index < 0 || *index >= vertex_count)
        return fail(face + ": vertex index " + std::to_string(*index) + " out of range (" +
                    std::to_string(vertex_count) + " vertices)");
      poly.push_back(static_cast<std::int32_t>(*index));
    }
    if (static_cast<std::int64_t>(mesh.triangles.size()) + *n - 2 > limits.max_triangles)
      return fail(face + ": triangle count (after triangulation) exceeds the limit of " +
                  std::to_string(limits.max_triangles) + " triangles per mesh");
    if (!triangulate_polygon(mesh.vertices, poly, mesh.triangles))
      return fail(face + " is a non-convex polygon with too many corners (" + std::to_string(*n) + ")");
  }
  if (lines.next())
    return fail("count mismatch: data after the " + std::to_string(vertex_count) + " vertices and " +
                std::to_string(face_count) + " faces declared in the header");
  mesh.tags.assign(mesh.triangles.size(), FaceTag::surface);
  return mesh;
}

Result<Mesh> read_obj(const std::filesystem::path& path, const MeshReadLimits& limits) {
  const std::string file = path.string();
  Result<std::string> text = read_text(path, limits.max_file_bytes);
  if (!text) return text.error();
  if (Status s = check_obj_counts(*text, file, limits); !s) return s.error();
  std::istringstream in(*text);
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  NoMaterials no_materials;
  const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, &no_materials, true);
  if (!err.empty()) return Error{file + ": " + first_line(err)};
  if (!ok) return Error{file + ": not a readable OBJ file"};
  if (!warn.empty()) return Error{file + ": " + first_line(warn)};

  Mesh mesh;
  const std::size_t vertex_count = attrib.vertices.size() / 3;
  mesh.vertices = exact_obj_positions(*text);
  if (mesh.vertices.size() != vertex_count) {  // unusual syntax: keep tinyobjloader's rounded values
    mesh.vertices.clear();
    for (std::size_t v = 0; v < vertex_count; ++v)
      mesh.vertices.emplace_back(attrib.vertices[3 * v], attrib.vertices[3 * v + 1], attrib.vertices[3 * v + 2]);
  }
  for (const tinyobj::shape_t& shape : shapes) {
    const FaceTag tag = shape.name == "cut" ? FaceTag::cut : FaceTag::surface;
    std::size_t offset = 0;
    for (const unsigned char corners : shape.mesh.num_face_vertices) {
      if (corners != 3) return Error{file + ": face with " + std::to_string(corners) + " corners left untriangulated"};
      Triangle t;
      for (int i = 0; i < 3; ++i) {
        const int index = shape.mesh.indices[offset + i].vertex_index;
        if (index < 0 || static_cast<std::size_t>(index) >= vertex_count)
          return Error{file + ": face references vertex " + std::to_string(index + 1) + " out of range (" +
                       std::to_string(vertex_count) + " vertices)"};
        t[i] = index;
      }
      offset += 3;
      mesh.add_triangle(t[0], t[1], t[2], tag);
    }
  }
  return mesh;
}

Result<Mesh> read_mesh(const std::filesystem::path& path, const MeshReadLimits& limits) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".off") return read_off(path, limits);
  if (ext == ".obj") return read_obj(path, limits);
  return Error{path.string() + ": unknown mesh format '" + ext + "' (expected .off or .obj)"};
}

Status write_obj(const Mesh& mesh, const std::filesystem::path& path) {
  assert(mesh.tags.size() == mesh.triangles.size());
  std::string out = "# shatterbench mesh\n";
  out.reserve(mesh.vertices.size() * 60 + mesh.triangles.size() * 24);
  for (const Vec3& p : mesh.vertices) append_vertex(out, "v ", p);
  for (const FaceTag tag : {FaceTag::surface, FaceTag::cut}) {
    if (std::find(mesh.tags.begin(), mesh.tags.end(), tag) == mesh.tags.end()) continue;
    out += tag == FaceTag::cut ? "g cut\n" : "g surface\n";
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
      if (mesh.tags[f] == tag) append_face(out, "f ", mesh.triangles[f], 1);
  }
  return write_text(out, path);
}

Status write_off(const Mesh& mesh, const std::filesystem::path& path) {
  std::string out = "OFF\n" + std::to_string(mesh.vertices.size()) + " " + std::to_string(mesh.triangles.size()) + " 0\n";
  out.reserve(mesh.vertices.size() * 60 + mesh.triangles.size() * 24);
  for (const Vec3& p : mesh.vertices) append_vertex(out, "", p);
  for (const Triangle& t : mesh.triangles) append_face(out, "3 ", t, 0);
  return write_text(out, path);
}

}  // namespace shatter
