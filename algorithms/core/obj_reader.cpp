/// read_obj (declared in mesh_io.h): one strict pass over the statements of an OBJ text.
///
/// Design note. tinyobjloader was lenient where a benchmark must not be: it read `v 1 1 foo` and
/// `v 1,5 2 3` as something, kept positions in float, stored corner counts in 8 bits and triangulated
/// large polygons in quadratic time. The reader needs positions, faces, group names and a game asset's
/// normals, UVs and materials, so it reads them itself with the shared lexical layer (mesh_text.h) and
/// triangulation (polygon_triangulation.h): every limit is counted as a statement is read, whatever
/// the line endings. A face's `vt` and `vn` indices are kept per polygon corner and given to the
/// triangles the polygon is split into (a triangle corner takes the first polygon corner with its
/// vertex); material libraries are read by material_library.h.

#include "algorithms/core/asset_reference.h"
#include "algorithms/core/bounded_read.h"
#include "algorithms/core/material_library.h"
#include "algorithms/core/mesh_io.h"
#include "algorithms/core/mesh_text.h"
#include "algorithms/core/polygon_triangulation.h"

#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace shatter {
namespace {

/// Statements that carry nothing a solid needs: read past without a check of their content.
constexpr std::array<std::string_view, 15> kSkipped = {
    "vp",  "s",     "usemap",   "maplib",   "l",          "p",         "mg",   "lod",
    "bevel", "c_interp", "d_interp", "shadow_obj", "trace_obj", "ctech", "stech"};

/// Free-form geometry statements: they describe surfaces this reader cannot triangulate.
constexpr std::array<std::string_view, 13> kFreeForm = {"cstype", "deg",  "bmat", "step", "curv", "curv2", "surf",
                                                        "parm",   "trim", "hole", "scrv", "sp",   "end"};

bool one_of(std::string_view key, std::span<const std::string_view> list) {
  return std::find(list.begin(), list.end(), key) != list.end();
}

/// The faces read so far: corners of all faces in one array, each face's first corner, line, tag and
/// material.
struct FaceList {
  std::vector<std::int32_t> corners;    ///< 0-based vertex indices, not yet checked against the count
  std::vector<std::int32_t> uvs;        ///< per corner: 0-based `vt` index, or -1 when the corner has none
  std::vector<std::int32_t> normals;    ///< per corner: 0-based `vn` index, or -1 when the corner has none
  std::vector<std::size_t> first;       ///< #faces + 1 offsets into `corners`
  std::vector<std::int64_t> line;       ///< #faces, line of the `f` statement
  std::vector<FaceTag> tag;             ///< #faces
  std::vector<std::int32_t> material;   ///< #faces, index into the names `usemtl` gave, -1 before any
};

/// One face corner: 0-based vertex, texture coordinate and normal index (-1: not given).
struct Corner {
  std::int64_t v = -1;
  std::int64_t vt = -1;
  std::int64_t vn = -1;
};

/// A 1-based (or, negative, relative to `so_far`) OBJ index to 0-based; `what` names the kind.
Result<std::int64_t> resolve_index(std::int64_t i, std::int64_t so_far, const char* what) {
  if (i == 0) return Error{std::string(what) + " index 0 (OBJ counts from 1)"};
  if (i < 0) {
    if (-i > so_far)
      return Error{"relative " + std::string(what) + " index " + std::to_string(i) + " reaches before the first one"};
    return so_far + i;
  }
  return i - 1;
}

/// Parses one corner `v`, `v/vt`, `v//vn` or `v/vt/vn` to 0-based indices; negative indices count
/// back from the counts read so far (`so_far`: vertices, texture coordinates, normals).
Result<Corner> parse_corner(std::string_view token, const std::array<std::int64_t, 3>& so_far) {
  const std::size_t slash = token.find('/');
  const Result<std::int64_t> v = parse_integer(token.substr(0, slash));
  if (!v) return v.error();
  Corner c;
  if (slash != std::string_view::npos) {
    std::string_view rest = token.substr(slash + 1);
    const std::size_t second = rest.find('/');
    const std::string_view vt = rest.substr(0, second);
    const std::string_view vn = second == std::string_view::npos ? std::string_view() : rest.substr(second + 1);
    const Error malformed{"corner '" + std::string(token.substr(0, 40)) + "' is malformed"};
    if (!vt.empty()) {
      const Result<std::int64_t> t = parse_integer(vt);
      if (!t) return malformed;
      const Result<std::int64_t> r = resolve_index(*t, so_far[1], "texture coordinate");
      if (!r) return r.error();
      c.vt = *r;
    }
    if (second != std::string_view::npos) {
      const Result<std::int64_t> n = parse_integer(vn);
      if (!n) return malformed;
      const Result<std::int64_t> r = resolve_index(*n, so_far[2], "normal");
      if (!r) return r.error();
      c.vn = *r;
    }
  }
  if (*v == 0) return Error{"vertex index 0 (OBJ counts vertices from 1)"};
  if (*v < 0) {
    if (-*v > so_far[0])
      return Error{"relative vertex index " + std::to_string(*v) + " reaches before the first vertex"};
    c.v = so_far[0] + *v;
  } else {
    c.v = *v - 1;
  }
  return c;
}

/// The material libraries an OBJ named, read as their `mtllib` statements are met.
struct Libraries {
  std::vector<std::string> names;     ///< as the `mtllib` statements wrote them
  std::vector<MaterialSlot> slots;    ///< every library's materials, texture paths relative to the OBJ's folder
  std::unordered_set<std::string> read;  ///< canonical paths already read (a library named again is not read again)
  std::uintmax_t bytes = 0;           ///< bytes of the libraries read
};

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
  std::vector<Vec3> normals;
  std::vector<Vec2> uvs;
  Libraries libraries;
  std::vector<std::string> used;        // material names in the order `usemtl` first gave them
  std::unordered_map<std::string, std::int32_t> used_index;  // name -> its index in `used`
  std::vector<std::int64_t> used_line;  // line of each name's first `usemtl`
  std::int32_t material = -1;
  const auto past_limit = [&](std::size_t count) { return static_cast<std::int64_t>(count) >= limits.max_vertices; };
  while (lines.next()) {
    const auto& tokens = lines.tokens();
    const std::string_view key = tokens[0];
    const std::int64_t line = lines.line();
    const auto numbers = static_cast<std::int64_t>(tokens.size()) - 1;
    if (key == "v") {
      if (past_limit(mesh.vertices.size()))
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
    } else if (key == "vn" || key == "vt") {
      const bool normal = key == "vn";
      if (past_limit(normal ? normals.size() : uvs.size()))
        return fail(line, std::string(normal ? "normal" : "texture coordinate") + " count exceeds the limit of " +
                              std::to_string(limits.max_vertices) + " per mesh");
      if (normal ? numbers != 3 : numbers != 2 && numbers != 3)
        return fail(line, std::string(key) + " has " + std::to_string(numbers) + " numbers, expected " +
                              (normal ? "x y z" : "u v or u v w"));
      double value[3];
      for (std::int64_t i = 0; i < numbers; ++i) {
        const Result<double> x = parse_finite_double(tokens[static_cast<std::size_t>(i + 1)]);
        if (!x) return fail(line, std::string(key) + ": " + x.error().message);
        value[i] = *x;
      }
      if (normal) normals.emplace_back(value[0], value[1], value[2]);
      else uvs.emplace_back(value[0], value[1]);  // w (a 3D texture's depth) is not kept
    } else if (key == "f") {
      if (numbers < 3) return fail(line, "face has " + std::to_string(numbers) + " corners (at least 3 needed)");
      if (numbers > kMaxPolygonCorners)
        return fail(line, "face has " + std::to_string(numbers) + " corners, past the limit of " +
                              std::to_string(kMaxPolygonCorners) + " corners per polygon");
      triangles += numbers - 2;
      if (triangles > limits.max_triangles)
        return fail(line, "triangle count (after triangulation) exceeds the limit of " +
                              std::to_string(limits.max_triangles) + " triangles per mesh");
      const std::array<std::int64_t, 3> so_far = {static_cast<std::int64_t>(mesh.vertices.size()),
                                                  static_cast<std::int64_t>(uvs.size()),
                                                  static_cast<std::int64_t>(normals.size())};
      for (std::int64_t i = 1; i <= numbers; ++i) {
        const Result<Corner> c = parse_corner(tokens[static_cast<std::size_t>(i)], so_far);
        if (!c) return fail(line, "face: " + c.error().message);
        if (c->v >= limits.max_vertices)
          return fail(line, "face: vertex index " + std::to_string(c->v + 1) + " is past the limit of " +
                                std::to_string(limits.max_vertices) + " vertices per mesh");
        if (c->vt >= limits.max_vertices || c->vn >= limits.max_vertices)
          return fail(line, "face: a texture coordinate or normal index is past the limit of " +
                                std::to_string(limits.max_vertices) + " per mesh");
        faces.corners.push_back(static_cast<std::int32_t>(c->v));
        faces.uvs.push_back(static_cast<std::int32_t>(c->vt));
        faces.normals.push_back(static_cast<std::int32_t>(c->vn));
      }
      faces.first.push_back(faces.corners.size());
      faces.line.push_back(line);
      faces.tag.push_back(tag);
      faces.material.push_back(material);
    } else if (key == "g" || key == "o") {
      tag = tokens.size() != 2       ? FaceTag::surface
            : tokens[1] == "cut"    ? FaceTag::cut
            : tokens[1] == "repair" ? FaceTag::repair
                                    : FaceTag::surface;
    } else if (key == "usemtl") {
      if (tokens.size() < 2) return fail(line, "'usemtl' without a material name");
      const std::string name = joined_tokens(tokens, 1);
      const auto [found, added] = used_index.try_emplace(name, static_cast<std::int32_t>(used.size()));
      material = found->second;
      if (added) {
        used.push_back(name);
        used_line.push_back(line);
      }
    } else if (key == "mtllib") {
      if (tokens.size() < 2) return fail(line, "'mtllib' without a file name");
      // Each token is one library (the format's rule); a name with spaces is tried whole first.
      std::error_code ec;
      std::vector<std::string> names = {joined_tokens(tokens, 1)};
      if (tokens.size() > 2 && !std::filesystem::exists(path.parent_path() / names[0], ec))
        names.assign(tokens.begin() + 1, tokens.end());
      for (const std::string& name : names) {
        // Only a regular file inside the OBJ's folder (asset_reference.h), each read once, all of them
        // together within one mesh file's size limit.
        Result<std::filesystem::path> library =
            resolve_reference(path.parent_path(), name, limits.max_file_bytes, "material library");
        if (!library) return fail(line, library.error().message);
        if (!libraries.read.insert(library->string()).second) continue;
        libraries.bytes += std::filesystem::file_size(*library, ec);
        if (libraries.bytes > limits.max_file_bytes)
          return fail(line, "material libraries: more than the limit of " + std::to_string(limits.max_file_bytes) +
                                " bytes in all");
        Result<std::vector<MaterialSlot>> slots = read_mtl(*library, limits);
        if (!slots) return fail(line, "material library: " + slots.error().message);
        const std::filesystem::path folder = std::filesystem::path(name).parent_path();
        for (MaterialSlot& slot : *slots) {
          if (!slot.base_color_texture.empty())
            if (Status t = check_reference_text(slot.base_color_texture, "texture"); !t)
              return fail(line, library->string() + ": " + t.error().message);
          if (!slot.base_color_texture.empty() && !folder.empty())
            slot.base_color_texture = (folder / slot.base_color_texture).lexically_normal().string();
          libraries.slots.push_back(std::move(slot));
        }
        libraries.names.push_back(name);
      }
    } else if (one_of(key, kFreeForm)) {
      return fail(line, "free-form geometry ('" + std::string(key) + "') is not supported");
    } else if (!one_of(key, kSkipped)) {
      return fail(line, "unknown statement '" + std::string(key.substr(0, 40)) + "'");
    }
  }

  // Materials: a slot per name used, from the libraries when the file names any (an unknown name is
  // then an error), by name alone when it names none; "default" for faces before the first usemtl.
  std::vector<MaterialSlot> slots;
  std::unordered_map<std::string, std::size_t> defined;  // name -> its last definition in the libraries
  for (std::size_t k = 0; k < libraries.slots.size(); ++k) defined[libraries.slots[k].name] = k;
  for (std::size_t m = 0; m < used.size(); ++m) {
    MaterialSlot slot;
    slot.name = used[m];
    if (!libraries.names.empty()) {
      // The last definition wins, as in one library.
      const auto found = defined.find(used[m]);
      if (found == defined.end()) {
        std::string names;
        for (const std::string& n : libraries.names) names += (names.empty() ? "" : "', '") + n;
        return fail(used_line[m], "material '" + used[m] + "' not in '" + names + "'");
      }
      slot = libraries.slots[found->second];
    }
    slots.push_back(std::move(slot));
  }
  std::int32_t default_slot = -1;
  if (!used.empty() && std::find(faces.material.begin(), faces.material.end(), -1) != faces.material.end()) {
    const auto named = std::find(used.begin(), used.end(), "default");
    default_slot = static_cast<std::int32_t>(named - used.begin());
    if (named == used.end()) {
      MaterialSlot whole;
      whole.name = "default";
      slots.push_back(whole);
    }
  }

  const auto vertex_count = static_cast<std::int64_t>(mesh.vertices.size());
  for (std::size_t f = 0; f + 1 < faces.first.size(); ++f)
    for (std::size_t c = faces.first[f]; c < faces.first[f + 1]; ++c) {
      if (faces.uvs[c] >= static_cast<std::int64_t>(uvs.size()))
        return fail(faces.line[f], "face references texture coordinate " + std::to_string(faces.uvs[c] + 1) +
                                       " out of range (" + std::to_string(uvs.size()) + " texture coordinates)");
      if (faces.normals[c] >= static_cast<std::int64_t>(normals.size()))
        return fail(faces.line[f], "face references normal " + std::to_string(faces.normals[c] + 1) +
                                       " out of range (" + std::to_string(normals.size()) + " normals)");
    }
  // A channel is kept only when every corner has it (a renderer cannot draw half a UV layout).
  const auto all_given = [](const std::vector<std::int32_t>& index) {
    return !index.empty() && std::find(index.begin(), index.end(), -1) == index.end();
  };
  AttributeLayout layout;
  layout.normals = all_given(faces.normals);
  layout.uv_sets = all_given(faces.uvs) ? 1 : 0;
  const std::size_t stride = static_cast<std::size_t>(layout.stride());
  mesh.attributes.layout = layout;
  mesh.attributes.slots = std::move(slots);

  mesh.triangles.reserve(static_cast<std::size_t>(triangles));
  if (stride > 0) mesh.attributes.corners.reserve(static_cast<std::size_t>(triangles) * 3 * stride);
  std::vector<Triangle> made;
  std::unordered_map<std::int32_t, std::size_t> corner_of;
  for (std::size_t f = 0; f + 1 < faces.first.size(); ++f) {
    const std::size_t first = faces.first[f];
    const std::span<const std::int32_t> poly(faces.corners.data() + first, faces.first[f + 1] - first);
    for (const std::int32_t v : poly)
      if (v >= vertex_count)
        return fail(faces.line[f], "face references vertex " + std::to_string(v + 1) + " out of range (" +
                                       std::to_string(vertex_count) + " vertices)");
    made.clear();
    if (Status s = triangulate_polygon(mesh.vertices, poly, made); !s) return fail(faces.line[f], "face: " + s.error().message);
    // Each triangle corner's place in the polygon (its first, when a vertex repeats): a search for the
    // few corners of an ordinary face, a table for a large polygon (linear in its corners).
    if (stride > 0 && poly.size() > 16) {
      corner_of.clear();
      for (std::size_t k = poly.size(); k-- > 0;) corner_of[poly[k]] = first + k;
    }
    for (const Triangle& t : made) {
      mesh.add_triangle(t[0], t[1], t[2], faces.tag[f]);
      if (!mesh.attributes.slots.empty())
        mesh.attributes.materials.push_back(faces.material[f] >= 0 ? faces.material[f] : default_slot);
      if (stride == 0) continue;
      for (const std::int32_t v : t) {
        const std::size_t c = poly.size() > 16
                                  ? corner_of.at(v)
                                  : first + static_cast<std::size_t>(std::find(poly.begin(), poly.end(), v) - poly.begin());
        CornerValues& out = mesh.attributes.corners;
        if (layout.normals) {
          const Vec3& n = normals[static_cast<std::size_t>(faces.normals[c])];
          out.insert(out.end(), {n.x(), n.y(), n.z()});
        }
        if (layout.uv_sets > 0) {
          const Vec2& uv = uvs[static_cast<std::size_t>(faces.uvs[c])];
          out.insert(out.end(), {uv.x(), uv.y()});
        }
      }
    }
  }
  return mesh;
}

}  // namespace shatter
