#include "algorithms/assets/mesh_codec.h"

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/mesh_attributes.h"

#include <algorithm>

namespace shatter {
namespace {

void write_attributes(BinaryWriter& w, const MeshAttributes& a, const std::vector<const TextureImage*>& images) {
  w.value(static_cast<std::uint8_t>(a.layout.normals));
  w.value(static_cast<std::int32_t>(a.layout.uv_sets));
  w.value(static_cast<std::uint8_t>(a.layout.tangents));
  w.value(static_cast<std::uint64_t>(a.corners.size()));
  w.bytes(a.corners.data(), a.corners.size() * sizeof(double));
  w.value(static_cast<std::uint64_t>(a.materials.size()));
  w.bytes(a.materials.data(), a.materials.size() * sizeof(std::int32_t));
  w.value(static_cast<std::uint64_t>(a.slots.size()));
  for (const MaterialSlot& slot : a.slots) {
    w.text(slot.name);
    w.bytes(slot.base_color.data(), sizeof slot.base_color);
    w.text(slot.base_color_texture);
    const auto image = std::find(images.begin(), images.end(), slot.base_color_image.get());
    w.value(slot.base_color_image ? static_cast<std::int64_t>(image - images.begin()) : std::int64_t{-1});
  }
  w.value(a.cut.material);
  w.value(a.cut.uv_scale);
}

bool read_attributes(BinaryReader& r, MeshAttributes& a, const std::vector<std::shared_ptr<const TextureImage>>& images) {
  a.layout.normals = r.value<std::uint8_t>() != 0;
  a.layout.uv_sets = r.value<std::int32_t>();
  a.layout.tangents = r.value<std::uint8_t>() != 0;
  if (a.layout.uv_sets < 0 || a.layout.uv_sets > kMaxUvSets) return false;
  const auto corners = r.value<std::uint64_t>();
  if (!r.ok() || corners > r.left() / sizeof(double)) return false;
  a.corners.resize(static_cast<std::size_t>(corners));
  r.bytes(a.corners.data(), a.corners.size() * sizeof(double));
  const auto materials = r.value<std::uint64_t>();
  if (!r.ok() || materials > r.left() / sizeof(std::int32_t)) return false;
  a.materials.resize(static_cast<std::size_t>(materials));
  r.bytes(a.materials.data(), a.materials.size() * sizeof(std::int32_t));
  const auto slots = r.value<std::uint64_t>();
  if (!r.ok() || slots > r.left()) return false;
  a.slots.resize(static_cast<std::size_t>(slots));
  for (MaterialSlot& slot : a.slots) {
    slot.name = r.text();
    r.bytes(slot.base_color.data(), sizeof slot.base_color);
    slot.base_color_texture = r.text();
    const auto image = r.value<std::int64_t>();
    if (image < -1 || image >= static_cast<std::int64_t>(images.size())) return false;
    if (image >= 0) slot.base_color_image = images[static_cast<std::size_t>(image)];
  }
  a.cut.material = r.value<std::int32_t>();
  a.cut.uv_scale = r.value<double>();
  return r.ok();
}

/// The invariants of mesh_attributes.h that indexing relies on (a cut-face style is a later step's).
bool attributes_consistent(const Mesh& mesh) {
  const MeshAttributes& a = mesh.attributes;
  if (a.empty()) return true;
  const std::size_t faces = mesh.triangles.size();
  if (a.layout.tangents && !a.layout.normals) return false;
  if (a.corners.size() != 3 * faces * static_cast<std::size_t>(a.layout.stride())) return false;
  if (a.slots.empty() != a.materials.empty() || (!a.materials.empty() && a.materials.size() != faces)) return false;
  const auto slots = static_cast<std::int32_t>(a.slots.size());
  for (const std::int32_t m : a.materials)
    if (m < 0 || m >= slots) return false;
  return all_finite(a.corners.data(), a.corners.size());
}

}  // namespace

std::vector<const TextureImage*> embedded_images(std::span<const Mesh* const> meshes) {
  std::vector<const TextureImage*> images;
  for (const Mesh* m : meshes)
    for (const MaterialSlot& slot : m->attributes.slots)
      if (slot.base_color_image && std::find(images.begin(), images.end(), slot.base_color_image.get()) == images.end())
        images.push_back(slot.base_color_image.get());
  return images;
}

void write_images(BinaryWriter& w, const std::vector<const TextureImage*>& images) {
  w.value(static_cast<std::uint64_t>(images.size()));
  for (const TextureImage* image : images) {
    w.text(image->mime_type);
    w.text(std::string(image->bytes.begin(), image->bytes.end()));
  }
}

bool read_images(BinaryReader& r, std::vector<std::shared_ptr<const TextureImage>>& images) {
  const auto count = r.value<std::uint64_t>();
  if (!r.ok() || count > r.left()) return false;
  for (std::uint64_t i = 0; i < count && r.ok(); ++i) {
    auto image = std::make_shared<TextureImage>();
    image->mime_type = r.text();
    const std::string bytes = r.text();
    image->bytes.assign(bytes.begin(), bytes.end());
    images.push_back(std::move(image));
  }
  return r.ok();
}

void write_mesh(BinaryWriter& w, const Mesh& mesh, const std::vector<const TextureImage*>& images) {
  w.value(static_cast<std::uint64_t>(mesh.vertices.size()));
  w.value(static_cast<std::uint64_t>(mesh.triangles.size()));
  for (const Vec3& v : mesh.vertices) w.bytes(v.data(), 3 * sizeof(double));
  for (const Triangle& t : mesh.triangles) w.bytes(t.data(), 3 * sizeof(std::int32_t));
  w.bytes(mesh.tags.data(), mesh.tags.size() * sizeof(FaceTag));
  write_attributes(w, mesh.attributes, images);
}

bool read_mesh(BinaryReader& r, Mesh& mesh, const std::vector<std::shared_ptr<const TextureImage>>& images) {
  const auto nv = r.value<std::uint64_t>();
  const auto nt = r.value<std::uint64_t>();
  if (!r.ok() || nv > r.left() / (3 * sizeof(double)) || nt > r.left() / (3 * sizeof(std::int32_t))) return false;
  mesh.vertices.resize(static_cast<std::size_t>(nv));
  mesh.triangles.resize(static_cast<std::size_t>(nt));
  mesh.tags.resize(static_cast<std::size_t>(nt));
  for (Vec3& v : mesh.vertices) r.bytes(v.data(), 3 * sizeof(double));
  for (Triangle& t : mesh.triangles) r.bytes(t.data(), 3 * sizeof(std::int32_t));
  r.bytes(mesh.tags.data(), mesh.tags.size() * sizeof(FaceTag));
  if (!read_attributes(r, mesh.attributes, images) || !r.ok()) return false;
  for (const Vec3& v : mesh.vertices)
    if (!v.allFinite()) return false;
  for (const FaceTag t : mesh.tags)
    if (t != FaceTag::surface && t != FaceTag::cut && t != FaceTag::repair) return false;
  for (const Triangle& t : mesh.triangles)
    for (const std::int32_t i : t)
      if (i < 0 || static_cast<std::uint64_t>(i) >= nv) return false;
  return attributes_consistent(mesh);
}

std::string encode_mesh(const Mesh& mesh) {
  BinaryWriter w;
  const Mesh* one[] = {&mesh};
  const std::vector<const TextureImage*> images = embedded_images(one);
  write_images(w, images);
  write_mesh(w, mesh, images);
  return w.data();
}

Result<Mesh> decode_mesh(const std::string& bytes, const std::string& what) {
  BinaryReader r(bytes);
  std::vector<std::shared_ptr<const TextureImage>> images;
  Mesh mesh;
  if (!read_images(r, images) || !read_mesh(r, mesh, images) || !r.at_end())
    return Error{what + ": the mesh handed back is damaged or incomplete"};
  return mesh;
}

}  // namespace shatter
