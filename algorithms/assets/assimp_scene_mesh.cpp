#include "algorithms/assets/assimp_scene_mesh.h"

#include "algorithms/core/asset_reference.h"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

namespace shatter {
namespace {

/// One placement of an assimp mesh: the mesh and its node's accumulated transform.
struct Instance {
  const aiMesh* mesh = nullptr;
  Eigen::Matrix4d transform = Eigen::Matrix4d::Identity();
};

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
  return out;
}

/// Every mesh placement under `node`, depth first; `depth` bounds a hostile file's nesting.
void collect(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& parent, std::vector<Instance>& out,
             int depth) {
  if (depth > 1024) return;  // ValidateDataStructure refuses cycles; this bounds the recursion anyway
  const Eigen::Matrix4d transform = parent * to_eigen(node.mTransformation);
  for (unsigned i = 0; i < node.mNumMeshes; ++i)
    if (node.mMeshes[i] < scene.mNumMeshes) out.push_back({scene.mMeshes[node.mMeshes[i]], transform});
  for (unsigned i = 0; i < node.mNumChildren; ++i)
    if (node.mChildren[i] != nullptr) collect(scene, *node.mChildren[i], transform, out, depth + 1);
}

/// Number of 2D UV sets `mesh` has from set 0 on (a 1D or 3D set ends the run).
int uv_sets_of(const aiMesh& mesh) {
  int n = 0;
  while (n < kMaxUvSets && mesh.HasTextureCoords(static_cast<unsigned>(n)) && mesh.mNumUVComponents[n] == 2) ++n;
  return n;
}

std::string mesh_name(const aiMesh& mesh, std::size_t index) {
  const std::string name(mesh.mName.C_Str());
  return "mesh " + std::to_string(index) + (name.empty() ? std::string() : " '" + name.substr(0, 60) + "'");
}

/// MIME type of an embedded compressed texture from assimp's format hint ("png", "jpg", ...).
std::string mime_of(const aiTexture& texture) {
  const std::string hint(texture.achFormatHint);
  if (hint == "png") return "image/png";
  if (hint == "jpg" || hint == "jpeg") return "image/jpeg";
  return "image/" + hint;
}

/// The material slots: one per aiMaterial used, their names unique.
class SlotMaker {
 public:
  explicit SlotMaker(const aiScene& scene) : scene_(scene) {}

  /// The first texture reference refused (check_reference_text), or empty.
  std::string refused;

  /// The slot of material `index`, made on first use.
  std::int32_t slot_of(unsigned index, std::vector<MaterialSlot>& slots) {
    const auto found = slot_.find(index);
    if (found != slot_.end()) return found->second;
    MaterialSlot slot;
    if (index < scene_.mNumMaterials && scene_.mMaterials[index] != nullptr) fill(*scene_.mMaterials[index], slot);
    if (slot.name.empty()) slot.name = "material_" + std::to_string(index);
    const std::string base = slot.name;
    for (int k = 2; std::any_of(slots.begin(), slots.end(), [&](const MaterialSlot& s) { return s.name == slot.name; }); ++k)
      slot.name = base + "_" + std::to_string(k);
    slots.push_back(std::move(slot));
    const auto made = static_cast<std::int32_t>(slots.size() - 1);
    slot_[index] = made;
    return made;
  }

 private:
  void fill(const aiMaterial& material, MaterialSlot& slot) {
    slot.name = material.GetName().C_Str();
    aiColor4D base;
    aiColor3D diffuse;
    if (material.Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS) {
      slot.base_color = {base.r, base.g, base.b, base.a};
    } else if (material.Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS) {
      float opacity = 1.0f;
      if (material.Get(AI_MATKEY_OPACITY, opacity) != AI_SUCCESS) opacity = 1.0f;
      slot.base_color = {diffuse.r, diffuse.g, diffuse.b, opacity};
    }
    for (double& c : slot.base_color) c = std::isfinite(c) ? std::clamp(c, 0.0, 1.0) : 1.0;
    aiString path;
    if (material.GetTexture(aiTextureType_BASE_COLOR, 0, &path) != AI_SUCCESS &&
        material.GetTexture(aiTextureType_DIFFUSE, 0, &path) != AI_SUCCESS)
      return;
    const std::string file(path.C_Str());
    const aiTexture* texture = scene_.GetEmbeddedTexture(path.C_Str());
    // A texture file the asset names stays a reference inside its folder (asset_reference.h): it is
    // written into the fragments' files, so a path outside would travel with them.
    if (!file.starts_with('*') && texture == nullptr)
      if (Status s = check_reference_text(file, "texture"); !s && refused.empty()) refused = s.error().message;
    if (!file.starts_with('*')) slot.base_color_texture = file;
    if (texture == nullptr || texture->mHeight != 0 || texture->pcData == nullptr) return;  // not embedded, or raw texels
    auto& image = image_[texture];
    if (!image) {
      auto made = std::make_shared<TextureImage>();
      made->mime_type = mime_of(*texture);
      const auto* bytes = reinterpret_cast<const std::uint8_t*>(texture->pcData);
      made->bytes.assign(bytes, bytes + texture->mWidth);  // a compressed texture's size in bytes
      image = std::move(made);
    }
    slot.base_color_image = image;
  }

  const aiScene& scene_;
  std::map<unsigned, std::int32_t> slot_;
  std::map<const aiTexture*, std::shared_ptr<const TextureImage>> image_;
};

}  // namespace

Result<Mesh> mesh_from_assimp_scene(const aiScene& scene, const std::string& name, const MeshReadLimits& limits) {
  std::vector<Instance> instances;
  if (scene.mRootNode != nullptr) collect(scene, *scene.mRootNode, Eigen::Matrix4d::Identity(), instances, 0);
  // Only triangle meshes count (SortByPType has removed points and lines; a mesh may still hold none).
  std::erase_if(instances, [](const Instance& i) {
    return i.mesh == nullptr || i.mesh->mNumFaces == 0 || (i.mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0;
  });
  std::int64_t vertices = 0, triangles = 0;
  for (const Instance& i : instances) {
    vertices += i.mesh->mNumVertices;
    triangles += i.mesh->mNumFaces;
  }
  if (triangles == 0) return Error{name + ": the scene holds no triangles"};
  if (vertices > limits.max_vertices)
    return Error{name + ": vertex count " + std::to_string(vertices) + " exceeds the limit of " +
                 std::to_string(limits.max_vertices) + " vertices per mesh"};
  if (triangles > limits.max_triangles)
    return Error{name + ": triangle count " + std::to_string(triangles) + " exceeds the limit of " +
                 std::to_string(limits.max_triangles) + " triangles per mesh"};

  AttributeLayout layout{true, kMaxUvSets, true};
  for (const Instance& i : instances) {
    layout.normals = layout.normals && i.mesh->HasNormals();
    layout.uv_sets = std::min(layout.uv_sets, uv_sets_of(*i.mesh));
    layout.tangents = layout.tangents && i.mesh->HasTangentsAndBitangents();
  }
  layout.tangents = layout.tangents && layout.normals;

  Mesh mesh;
  mesh.attributes.layout = layout;
  mesh.vertices.reserve(static_cast<std::size_t>(vertices));
  mesh.triangles.reserve(static_cast<std::size_t>(triangles));
  mesh.attributes.corners.reserve(static_cast<std::size_t>(triangles) * 3 * static_cast<std::size_t>(layout.stride()));
  SlotMaker slots(scene);
  CornerValues& corners = mesh.attributes.corners;
  for (std::size_t m = 0; m < instances.size(); ++m) {
    const aiMesh& in = *instances[m].mesh;
    const Eigen::Matrix4d& t = instances[m].transform;
    const Eigen::Matrix3d linear = t.topLeftCorner<3, 3>();
    const Eigen::Matrix3d normal_matrix = linear.inverse().transpose();
    const bool mirrored = linear.determinant() < 0.0;
    const auto fail = [&](const std::string& what) { return Error{name + ": " + mesh_name(in, m) + " has " + what}; };
    if (!linear.allFinite() || !normal_matrix.allFinite() || !t.allFinite()) return fail("a singular or non-finite node transform");
    const auto first = static_cast<std::int32_t>(mesh.vertices.size());
    for (unsigned v = 0; v < in.mNumVertices; ++v) {
      const aiVector3D& p = in.mVertices[v];
      const Vec3 q = (t * Eigen::Vector4d(p.x, p.y, p.z, 1.0)).head<3>();
      if (!q.allFinite()) return fail("a non-finite position (vertex " + std::to_string(v) + ")");
      mesh.vertices.push_back(q);
    }
    const std::int32_t slot = slots.slot_of(in.mMaterialIndex, mesh.attributes.slots);
    for (unsigned f = 0; f < in.mNumFaces; ++f) {
      const aiFace& face = in.mFaces[f];
      if (face.mNumIndices != 3) continue;  // a point or line SortByPType left in a mixed mesh
      std::array<unsigned, 3> index = {face.mIndices[0], face.mIndices[1], face.mIndices[2]};
      if (mirrored) std::swap(index[1], index[2]);
      for (const unsigned i : index)
        if (i >= in.mNumVertices) return fail("a face index out of range (face " + std::to_string(f) + ")");
      mesh.add_triangle(first + static_cast<std::int32_t>(index[0]), first + static_cast<std::int32_t>(index[1]),
                        first + static_cast<std::int32_t>(index[2]), FaceTag::surface);
      mesh.attributes.materials.push_back(slot);
      for (const unsigned i : index) {
        Vec3 n = Vec3::Zero();
        if (layout.normals) {
          n = normal_matrix * Vec3(in.mNormals[i].x, in.mNormals[i].y, in.mNormals[i].z);
          if (n.norm() > 0.0) n.normalize();
          if (!n.allFinite()) return fail("a non-finite normal (vertex " + std::to_string(i) + ")");
          corners.insert(corners.end(), {n.x(), n.y(), n.z()});
        }
        for (int s = 0; s < layout.uv_sets; ++s) {
          const aiVector3D& uv = in.mTextureCoords[s][i];
          if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
            return fail("a non-finite UV (set " + std::to_string(s) + ", vertex " + std::to_string(i) + ")");
          corners.insert(corners.end(), {static_cast<double>(uv.x), static_cast<double>(uv.y)});
        }
        if (layout.tangents) {
          Vec3 tangent = linear * Vec3(in.mTangents[i].x, in.mTangents[i].y, in.mTangents[i].z);
          const Vec3 bitangent = linear * Vec3(in.mBitangents[i].x, in.mBitangents[i].y, in.mBitangents[i].z);
          if (tangent.norm() > 0.0) tangent.normalize();
          if (!tangent.allFinite() || !bitangent.allFinite())
            return fail("a non-finite tangent (vertex " + std::to_string(i) + ")");
          const double w = n.cross(tangent).dot(bitangent) < 0.0 ? -1.0 : 1.0;
          corners.insert(corners.end(), {tangent.x(), tangent.y(), tangent.z(), w});
        }
      }
    }
  }
  if (!slots.refused.empty()) return Error{name + ": " + slots.refused};
  if (mesh.triangles.empty()) return Error{name + ": the scene holds no triangles"};
  return mesh;
}

}  // namespace shatter
