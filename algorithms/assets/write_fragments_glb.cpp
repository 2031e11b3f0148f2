#include "algorithms/assets/write_fragments_glb.h"

#include "algorithms/core/mesh_text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace shatter {
namespace {

using json = nlohmann::json;

constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

/// The binary chunk and the JSON arrays that point into it.
class GlbBuilder {
 public:
  /// Appends `bytes` (4-byte aligned) as a buffer view and returns its index.
  int view(const void* data, std::size_t size, int target) {
    while (bin_.size() % 4 != 0) bin_.push_back(0);
    json v = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", size}};
    if (target != 0) v["target"] = target;
    const auto* p = static_cast<const std::uint8_t*>(data);
    bin_.insert(bin_.end(), p, p + size);
    views_.push_back(std::move(v));
    return static_cast<int>(views_.size() - 1);
  }
  /// A float accessor of `components` per element ("VEC2", "VEC3", "VEC4"), min/max when asked.
  int float_accessor(const std::vector<float>& values, int components, const char* type, bool bounds) {
    json a = {{"bufferView", view(values.data(), values.size() * sizeof(float), kArrayBuffer)},
              {"componentType", kFloat},
              {"count", values.size() / static_cast<std::size_t>(components)},
              {"type", type}};
    if (bounds) {
      std::vector<float> lo(static_cast<std::size_t>(components), std::numeric_limits<float>::max());
      std::vector<float> hi(static_cast<std::size_t>(components), std::numeric_limits<float>::lowest());
      for (std::size_t i = 0; i < values.size(); ++i) {
        const std::size_t c = i % static_cast<std::size_t>(components);
        lo[c] = std::min(lo[c], values[i]);
        hi[c] = std::max(hi[c], values[i]);
      }
      a["min"] = lo;
      a["max"] = hi;
    }
    accessors_.push_back(std::move(a));
    return static_cast<int>(accessors_.size() - 1);
  }
  /// An index accessor.
  int index_accessor(const std::vector<std::uint32_t>& indices) {
    accessors_.push_back({{"bufferView", view(indices.data(), indices.size() * sizeof(std::uint32_t), kElementArrayBuffer)},
                          {"componentType", kUnsignedInt},
                          {"count", indices.size()},
                          {"type", "SCALAR"}});
    return static_cast<int>(accessors_.size() - 1);
  }
  [[nodiscard]] json accessors() const { return accessors_; }
  [[nodiscard]] json views() const { return views_; }
  [[nodiscard]] const std::vector<std::uint8_t>& bin() const { return bin_; }

 private:
  std::vector<std::uint8_t> bin_;
  json views_ = json::array();
  json accessors_ = json::array();
};

/// A relative path as a URI reference: reserved and non-ASCII bytes percent-encoded, '/' kept.
std::string uri_of(const std::string& path) {
  std::string out;
  for (const unsigned char c : path) {
    if (std::isalnum(c) || std::strchr("-._~/", c) != nullptr) {
      out += static_cast<char>(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    }
  }
  return out;
}

/// The materials, textures and images of all fragments: one material per slot name.
class MaterialTable {
 public:
  /// The glTF material of `slot`, made on first use.
  int material_of(const MaterialSlot& slot, GlbBuilder& glb) {
    if (const auto found = by_name_.find(slot.name); found != by_name_.end()) return found->second;
    const auto& c = slot.base_color;
    json pbr = {{"baseColorFactor", {c[0], c[1], c[2], c[3]}}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}};
    if (slot.base_color_image || !slot.base_color_texture.empty()) pbr["baseColorTexture"] = {{"index", texture_of(slot, glb)}};
    json material = {{"name", slot.name}, {"pbrMetallicRoughness", std::move(pbr)}};
    if (c[3] < 1.0) material["alphaMode"] = "BLEND";
    materials_.push_back(std::move(material));
    const auto index = static_cast<int>(materials_.size() - 1);
    by_name_[slot.name] = index;
    return index;
  }
  /// Adds the arrays to the document (only those that have entries).
  void add_to(json& doc) const {
    if (!materials_.empty()) doc["materials"] = materials_;
    if (!images_.empty()) {
      doc["images"] = images_;
      doc["textures"] = textures_;
      doc["samplers"] = json::array({json::object()});
    }
  }

 private:
  int texture_of(const MaterialSlot& slot, GlbBuilder& glb) {
    const std::string key = slot.base_color_image ? std::string() : slot.base_color_texture;
    const auto found = slot.base_color_image ? by_image_.find(slot.base_color_image.get()) : by_image_.end();
    if (found != by_image_.end()) return found->second;
    if (!slot.base_color_image)
      if (const auto uri = by_uri_.find(key); uri != by_uri_.end()) return uri->second;
    json image;
    if (slot.base_color_image) {
      const TextureImage& bytes = *slot.base_color_image;
      image = {{"bufferView", glb.view(bytes.bytes.data(), bytes.bytes.size(), 0)},
               {"mimeType", bytes.mime_type.empty() ? "image/png" : bytes.mime_type}};
    } else {
      image = {{"uri", uri_of(slot.base_color_texture)}};
    }
    images_.push_back(std::move(image));
    textures_.push_back({{"source", images_.size() - 1}, {"sampler", 0}});
    const auto index = static_cast<int>(textures_.size() - 1);
    if (slot.base_color_image) by_image_[slot.base_color_image.get()] = index;
    else by_uri_[key] = index;
    return index;
  }

  json materials_ = json::array();
  json images_ = json::array();
  json textures_ = json::array();
  std::map<std::string, int> by_name_;
  std::map<const TextureImage*, int> by_image_;
  std::map<std::string, int> by_uri_;
};

/// The vertex arrays of one primitive; corners equal in position and attributes share a vertex.
struct Primitive {
  std::vector<float> positions, normals, tangents;
  std::array<std::vector<float>, kMaxUvSets> uvs;
  std::vector<std::uint32_t> indices;
  std::unordered_map<std::string, std::uint32_t> vertex_of;  ///< key: the vertex's float values
};

/// Adds corner k of triangle f of `mesh` (position relative to `origin`) to `p`.
void add_corner(Primitive& p, const Mesh& mesh, std::size_t f, int k, const Vec3& origin, const Vec3& face_normal) {
  const MeshAttributes& attr = mesh.attributes;
  const AttributeLayout& layout = attr.layout;
  const Vec3 q = mesh.vertices[static_cast<std::size_t>(mesh.triangles[f][static_cast<std::size_t>(k)])] - origin;
  std::vector<float> values = {static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z())};
  Vec3 n = face_normal;
  const double* c = layout.empty() ? nullptr : attr.corner(f, k);
  if (layout.normals) n = Vec3(c[0], c[1], c[2]);
  if (n.norm() > 0.0) n.normalize();
  values.insert(values.end(), {static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z())});
  for (int s = 0; s < layout.uv_sets; ++s) {
    const double* uv = c + layout.uv_offset(s);
    values.insert(values.end(), {static_cast<float>(uv[0]), static_cast<float>(1.0 - uv[1])});
  }
  if (layout.tangents) {
    const double* t = c + layout.tangent_offset();
    Vec3 d(t[0], t[1], t[2]);
    if (d.norm() > 0.0) d.normalize();
    values.insert(values.end(), {static_cast<float>(d.x()), static_cast<float>(d.y()), static_cast<float>(d.z()),
                                 t[3] < 0.0 ? -1.0f : 1.0f});
  }
  const std::string key(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float));
  const auto [it, made] = p.vertex_of.emplace(key, static_cast<std::uint32_t>(p.positions.size() / 3));
  p.indices.push_back(it->second);
  if (!made) return;
  p.positions.insert(p.positions.end(), values.begin(), values.begin() + 3);
  p.normals.insert(p.normals.end(), values.begin() + 3, values.begin() + 6);
  std::size_t at = 6;
  for (int s = 0; s < layout.uv_sets; ++s, at += 2)
    p.uvs[static_cast<std::size_t>(s)].insert(p.uvs[static_cast<std::size_t>(s)].end(), values.begin() + static_cast<std::ptrdiff_t>(at),
                                              values.begin() + static_cast<std::ptrdiff_t>(at + 2));
  if (layout.tangents) p.tangents.insert(p.tangents.end(), values.begin() + static_cast<std::ptrdiff_t>(at), values.end());
}

/// Primitive keys of a fragment without material slots (slots are >= 0).
constexpr std::int32_t kPlainCut = -2;
constexpr std::int32_t kPlainSurface = -1;

/// The material of the cut faces of fragments without material slots: a warm red-brown, so that beside
/// glTF's default white surface every cut reads as the inside of the solid.
const MaterialSlot& plain_interior_slot() {
  static const MaterialSlot slot{.name = "interior", .base_color = {0.72, 0.33, 0.2, 1.0}, .base_color_texture = {}, .base_color_image = {}};
  return slot;
}

/// The glTF mesh of `fragment` (its primitives), or an error naming it.
Result<json> mesh_of(const Fragment& fragment, const std::string& name, GlbBuilder& glb, MaterialTable& materials) {
  const Mesh& mesh = fragment.mesh;
  const MeshAttributes& attr = mesh.attributes;
  for (const Vec3& p : mesh.vertices)
    if (!p.allFinite()) return Error{name + ": a vertex is not finite"};
  for (const double v : attr.corners)
    if (!std::isfinite(v)) return Error{name + ": a corner attribute is not finite"};
  // Faces grouped by material slot, in slot order. Without slots, the surface (and repair) faces are
  // kPlainSurface with glTF's default material and the cut faces kPlainCut with the plain interior one.
  std::map<std::int32_t, Primitive> primitives;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    std::int32_t slot = kPlainSurface;
    if (!attr.materials.empty()) {
      slot = attr.materials[f];
      if (slot >= static_cast<std::int32_t>(attr.slots.size())) slot = kPlainSurface;  // not a slot: the default material
    } else if (mesh.tags[f] == FaceTag::cut) {
      slot = kPlainCut;
    }
    const Triangle& t = mesh.triangles[f];
    const Vec3 face_normal = (mesh.vertices[static_cast<std::size_t>(t[1])] - mesh.vertices[static_cast<std::size_t>(t[0])])
                                 .cross(mesh.vertices[static_cast<std::size_t>(t[2])] - mesh.vertices[static_cast<std::size_t>(t[0])]);
    Primitive& p = primitives[slot];
    for (int k = 0; k < 3; ++k) add_corner(p, mesh, f, k, fragment.mass.centroid, face_normal);
    if (p.positions.size() / 3 > std::numeric_limits<std::uint32_t>::max() - 3)
      return Error{name + ": more vertices than a uint32 index reaches"};
  }
  json out = json::array();
  for (const auto& [slot, p] : primitives) {
    json attributes = {{"POSITION", glb.float_accessor(p.positions, 3, "VEC3", true)},
                       {"NORMAL", glb.float_accessor(p.normals, 3, "VEC3", false)}};
    for (int s = 0; s < attr.layout.uv_sets; ++s)
      attributes["TEXCOORD_" + std::to_string(s)] = glb.float_accessor(p.uvs[static_cast<std::size_t>(s)], 2, "VEC2", false);
    if (attr.layout.tangents) attributes["TANGENT"] = glb.float_accessor(p.tangents, 4, "VEC4", false);
    json primitive = {{"attributes", std::move(attributes)}, {"indices", glb.index_accessor(p.indices)}, {"mode", 4}};
    if (slot >= 0) primitive["material"] = materials.material_of(attr.slots[static_cast<std::size_t>(slot)], glb);
    if (slot == kPlainCut) primitive["material"] = materials.material_of(plain_interior_slot(), glb);
    out.push_back(std::move(primitive));
  }
  return out;
}

void append_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xffu);
}

}  // namespace

Status write_fragments_glb(const std::filesystem::path& path, std::span<const Fragment> fragments) {
  GlbBuilder glb;
  MaterialTable materials;
  json nodes = json::array(), meshes = json::array(), roots = json::array();
  // Every slot becomes a material, used or not (the interior one even when no fragment has a cut face).
  for (const Fragment& f : fragments)
    for (const MaterialSlot& slot : f.mesh.attributes.slots) materials.material_of(slot, glb);
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "fragment_%03zu", i);
    const Vec3& c = fragments[i].mass.centroid;
    if (!c.allFinite()) return Error{path.string() + ": " + name + ": the centroid is not finite"};
    const double volume = fragments[i].mass.volume;
    if (!std::isfinite(volume)) return Error{path.string() + ": " + name + ": the volume is not finite"};
    json node = {{"name", name}, {"translation", {c.x(), c.y(), c.z()}}, {"extras", {{"volume", volume}}}};
    if (!fragments[i].mesh.triangles.empty()) {
      Result<json> primitives = mesh_of(fragments[i], path.string() + ": " + name, glb, materials);
      if (!primitives) return primitives.error();
      meshes.push_back({{"name", name}, {"primitives", std::move(*primitives)}});
      node["mesh"] = meshes.size() - 1;
    }
    nodes.push_back(std::move(node));
    roots.push_back(i);
  }
  json doc = {{"asset", {{"version", "2.0"}, {"generator", "shatterbench"}}}, {"scene", 0}};
  // glTF requires non-empty arrays: no fragments is an empty scene.
  doc["scenes"] = json::array({roots.empty() ? json::object() : json{{"nodes", roots}}});
  if (!nodes.empty()) doc["nodes"] = nodes;
  if (!meshes.empty()) doc["meshes"] = meshes;
  materials.add_to(doc);
  if (!glb.bin().empty()) {
    doc["buffers"] = json::array({{{"byteLength", glb.bin().size()}}});
    doc["bufferViews"] = glb.views();
    doc["accessors"] = glb.accessors();
  }

  std::string text = doc.dump();
  while (text.size() % 4 != 0) text += ' ';
  std::vector<std::uint8_t> bin = glb.bin();
  while (bin.size() % 4 != 0) bin.push_back(0);
  std::string out;
  const std::size_t total = 12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size());
  if (total > std::numeric_limits<std::uint32_t>::max()) return Error{path.string() + ": larger than a .glb can hold (4 GiB)"};
  out.reserve(total);
  append_u32(out, 0x46546C67u);  // "glTF"
  append_u32(out, 2);
  append_u32(out, static_cast<std::uint32_t>(total));
  append_u32(out, static_cast<std::uint32_t>(text.size()));
  append_u32(out, 0x4E4F534Au);  // "JSON"
  out += text;
  if (!bin.empty()) {
    append_u32(out, static_cast<std::uint32_t>(bin.size()));
    append_u32(out, 0x004E4942u);  // "BIN\0"
    out.append(reinterpret_cast<const char*>(bin.data()), bin.size());
  }
  return write_file_bytes(out, path);
}

}  // namespace shatter
