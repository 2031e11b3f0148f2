/// read_obj (declared in mesh_io.h): one strict pass over the statements of an OBJ text.
///
/// Design note. tinyobjloader was lenient where a benchmark must not be: it read `v 1 1 foo` and
/// `v 1,5 2 3` as something, kept positions in float, stored corner counts in 8 bits and triangulated
/// large polygons in quadratic time. The reader needs only positions, faces and group names, so it
/// reads them itself with the shared lexical layer (mesh_text.h) and triangulation
/// (polygon_triangulation.h): every limit is counted as a statement is read, whatever the line endings.

#include "algorithms/core/bounded_read.h"
#include "algorithms/core/mesh_io.h"
#include "algorithms/core/mesh_text.h"
#include "algorithms/core/polygon_triangulation.h"

#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace shatter {
namespace {

/// Statements that carry nothing a solid needs: read past without a check of their content.
constexpr std::array<std::string_view, 19> kSkipped = {
    "vt",    "vn",       "vp",       "s",          "mtllib",    "usemtl", "usemap", "maplib", "l",     "p",
    "mg",    "lod",      "bevel",    "c_interp",   "d_interp",  "shadow_obj", "trace_obj", "ctech", "stech"};

/// Free-form geometry statements: they describe surfaces this reader cannot triangulate.
constexpr std::array<std::string_view, 13> kFreeForm = {"cstype", "deg",  "bmat", "step", "curv", "curv2", "surf",
                                                        "parm",   "trim", "hole", "scrv", "sp",   "end"};

bool one_of(std::string_view key, std::span<const std::string_view> list) {
  return std::find(list.begin(), list.end(), key) != list.end();
}

/// The faces read so far: corners of all faces in one array, each face's first corner, line and tag.
struct FaceList {
  std::vector<std::int32_t> corners;    ///< 0-based vertex indices, not yet checked against the count
  std::vector<std::size_t> first;       ///< #faces + 1 offsets into `corners`
  std::vector<std::int64_t> line;       ///< #faces, line of the `f` statement
  std::vector<FaceTag> tag;             ///< #faces
};

/// Parses one corner `v`, `v/vt`, `v//vn` or `v/vt/vn` to its 0-based vertex index; negative
/// indices count back from the `vertices_so_far`-th vertex.
Result<std::int64_t> parse_corner(std::string_view token, std::int64_t vertices_so_far) {
  const std::size_t slash = token.find('/');
  const Result<std::int64_t> v = parse_integer(token.substr(0, slash));
  if (!v) return v.error();
  if (slash != std::string_view::npos) {
    std::string_view rest = token.substr(slash + 1);
    const std::size_t second = rest.find('/');
    const std::string_view vt = rest.substr(0, second);
    const std::string_view vn = second == std::string_view::npos ? std::string_view() : rest.substr(second + 1);
    if (!vt.empty() && !parse_integer(vt)) return Error{"corner '" + std::string(token.substr(0, 40)) + "' is malformed"};
    if (second != std::string_view::npos && !parse_integer(vn))
      return Error{"corner '" + std::string(token.substr(0, 40)) + "' is malformed"};
  }
  if (*v == 0) return Error{"vertex index 0 (OBJ counts vertices from 1)"};
  if (*v < 0) {
    if (-*v > vertices_so_far)
      return Error{"relative vertex index " + std::to_string(*v) + " reaches before the first vertex"};
    return vertices_so_far + *v;
  }
  return *v - 1;
}

}  // namespace

Result<Mesh> read_obj(const std::filesystem::path& path, const MeshReadLimits& limits) {
  const std::string file = path.string();
  Result<std::string> text = read_file_bounded(path, limits.max_file_bytes, "mesh file");
  if (!text) return text.error();
  TokenLines lines(*text);
  const auto fail = [&](std::int64_t line, const std::string& what) {
    return Error{file + ":" + std::to_string(line) + ": " + what};
  };

  Mesh mesh;
  FaceList faces;
  faces.first.push_back(0);
  FaceTag tag = FaceTag::surface;
  std::int64_t triangles = 0;
  while (lines.next()) {
    const auto& tokens = lines.tokens();
    const std::string_view key = tokens[0];
    const std::int64_t line = lines.line();
    const auto numbers = static_cast<std::int64_t>(tokens.size()) - 1;
    if (key == "v") {
      if (static_cast<std::int64_t>(mesh.vertices.size()) >= limits.max_vertices)
        return fail(line, "vertex count exceeds the limit of " + std::to_string(limits.max_vertices) + " vertices per mesh");
      if (numbers != 3 && numbers != 4 && numbers != 6)
        return fail(line, "vertex has " + std::to_string(numbers) +
                              " numbers, expected x y z, x y z w or x y z r g b");
      double value[6];
      for (std::int64_t i = 0; i < numbers; ++i) {
        const Result<double> x = parse_finite_double(tokens[static_cast<std::size_t>(i + 1)]);
        if (!x) return fail(line, "vertex: " + x.error().message);
        value[i] = *x;
      }
      if (numbers == 4 && value[3] != 1.0)
        return fail(line, "vertex weight w = " + std::string(tokens[4].substr(0, 40)) +
                              " is not supported (only w = 1 places the vertex at x y z)");
      mesh.vertices.emplace_back(value[0], value[1], value[2]);
    } else if (key == "f") {
      if (numbers < 3) return fail(line, "face has " + std::to_string(numbers) + " corners (at least 3 needed)");
      if (numbers > kMaxPolygonCorners)
        return fail(line, "face has " + std::to_string(numbers) + " corners, past the limit of " +
                              std::to_string(kMaxPolygonCorners) + " corners per polygon");
      triangles += numbers - 2;
      if (triangles > limits.max_triangles)
        return fail(line, "triangle count (after triangulation) exceeds the limit of " +
                              std::to_string(limits.max_triangles) + " triangles per mesh");
      for (std::int64_t i = 1; i <= numbers; ++i) {
        const Result<std::int64_t> v =
            parse_corner(tokens[static_cast<std::size_t>(i)], static_cast<std::int64_t>(mesh.vertices.size()));
        if (!v) return fail(line, "face: " + v.error().message);
        if (*v >= limits.max_vertices)
          return fail(line, "face: vertex index " + std::to_string(*v + 1) + " is past the limit of " +
                                std::to_string(limits.max_vertices) + " vertices per mesh");
        faces.corners.push_back(static_cast<std::int32_t>(*v));
      }
      faces.first.push_back(faces.corners.size());
      faces.line.push_back(line);
      faces.tag.push_back(tag);
    } else if (key == "g" || key == "o") {
      tag = tokens.size() != 2       ? FaceTag::surface
            : tokens[1] == "cut"    ? FaceTag::cut
            : tokens[1] == "repair" ? FaceTag::repair
                                    : FaceTag::surface;
    } else if (one_of(key, kFreeForm)) {
      return fail(line, "free-form geometry ('" + std::string(key) + "') is not supported");
    } else if (!one_of(key, kSkipped)) {
      return fail(line, "unknown statement '" + std::string(key.substr(0, 40)) + "'");
    }
  }

  const auto vertex_count = static_cast<std::int64_t>(mesh.vertices.size());
  mesh.triangles.reserve(static_cast<std::size_t>(triangles));
  std::vector<Triangle> made;
  for (std::size_t f = 0; f + 1 < faces.first.size(); ++f) {
    const std::span<const std::int32_t> poly(faces.corners.data() + faces.first[f], faces.first[f + 1] - faces.first[f]);
    for (const std::int32_t v : poly)
      if (v >= vertex_count)
        return fail(faces.line[f], "face references vertex " + std::to_string(v + 1) + " out of range (" +
                                       std::to_string(vertex_count) + " vertices)");
    made.clear();
    if (Status s = triangulate_polygon(mesh.vertices, poly, made); !s) return fail(faces.line[f], "face: " + s.error().message);
    for (const Triangle& t : made) mesh.add_triangle(t[0], t[1], t[2], faces.tag[f]);
  }
  return mesh;
}

}  // namespace shatter
