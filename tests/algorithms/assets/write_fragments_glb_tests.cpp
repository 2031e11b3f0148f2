#include "algorithms/assets/write_fragments_glb.h"
#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/mass_properties.h"
#include "algorithms/core/primitives.h"

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/scene.h>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace shatter;
namespace fs = std::filesystem;

namespace {

/// The UV every surface corner carries: an affine function of the position.
Vec2 uv_at(const Vec3& p) { return Vec2(0.25 + 0.5 * p.x() - 0.125 * p.z(), 0.75 * p.y() + 0.125 * p.z()); }

/// A box fragment of `size` at `center` whose faces at x = 0 are cut faces (interior material): flat
/// normals, affine UVs, tangents, the surface material with an embedded image.
Fragment box_fragment(const Vec3& size, const Vec3& center, const std::shared_ptr<const TextureImage>& image) {
  Fragment fragment;
  Mesh& mesh = fragment.mesh;
  mesh = make_box(size, center);
  MeshAttributes& a = mesh.attributes;
  a.layout = AttributeLayout{true, 1, true};
  MaterialSlot stone;
  stone.name = "stone";
  stone.base_color = {0.5, 0.25, 0.125, 1.0};
  stone.base_color_image = image;
  a.slots = {stone};
  a.materials.assign(mesh.triangles.size(), 0);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 n = (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).normalized();
    const Vec3 e = cut_plane_basis(n)[0];
    for (int k = 0; k < 3; ++k) {
      const Vec2 uv = uv_at(mesh.vertices[t[static_cast<std::size_t>(k)]]);
      a.corners.insert(a.corners.end(), {n.x(), n.y(), n.z(), uv.x(), uv.y(), e.x(), e.y(), e.z(), f % 2 == 0 ? 1.0 : -1.0});
    }
  }
  prepare_cut_faces(mesh, 1.0);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    if (mesh.vertices[t[0]].x() == 0.0 && mesh.vertices[t[1]].x() == 0.0 && mesh.vertices[t[2]].x() == 0.0) {
      mesh.tags[f] = FaceTag::cut;
      a.materials[f] = a.cut.material;
    }
  }
  fragment.mass = mass_properties(mesh);
  return fragment;
}

Vec3 vec(const aiVector3D& v) { return Vec3(v.x, v.y, v.z); }

}  // namespace

TEST_CASE("glb writer: two box fragments read back by assimp where they were, with their attributes", "[assets][glb]") {
  const fs::path dir = fs::temp_directory_path() / "shatter_write_fragments_glb";
  fs::remove_all(dir);
  fs::create_directories(dir);
  auto image = std::make_shared<TextureImage>();
  image->mime_type = "image/png";
  image->bytes = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 1, 2, 3, 4, 5};
  const std::vector<Fragment> fragments = {box_fragment(Vec3(1, 2, 3), Vec3(0.5, 1, 1.5), image),
                                           box_fragment(Vec3(0.5, 2, 3), Vec3(-0.25, 1, 1.5), image)};
  const fs::path path = dir / "fragments.glb";
  REQUIRE(write_fragments_glb(path, fragments).ok());

  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path.string(), 0);
  INFO(importer.GetErrorString());
  REQUIRE(scene != nullptr);
  REQUIRE(scene->mRootNode != nullptr);
  // Materials: "stone" with its colour and the embedded image, and the interior material.
  std::map<std::string, unsigned> material;
  for (unsigned m = 0; m < scene->mNumMaterials; ++m) material[scene->mMaterials[m]->GetName().C_Str()] = m;
  REQUIRE(material.count("stone") == 1);
  REQUIRE(material.count("interior") == 1);
  aiColor4D colour;
  REQUIRE(scene->mMaterials[material["stone"]]->Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS);
  CHECK(colour.r == 0.5f);
  CHECK(colour.g == 0.25f);
  CHECK(colour.b == 0.125f);
  CHECK(colour.a == 1.0f);
  REQUIRE(scene->mMaterials[material["interior"]]->Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS);
  CHECK(colour.r == 0.5f);
  aiString texture;
  REQUIRE(scene->mMaterials[material["stone"]]->GetTexture(aiTextureType_BASE_COLOR, 0, &texture) == AI_SUCCESS);
  const aiTexture* embedded = scene->GetEmbeddedTexture(texture.C_Str());
  REQUIRE(embedded != nullptr);
  CHECK(embedded->mHeight == 0);
  REQUIRE(embedded->mWidth == image->bytes.size());
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(embedded->pcData);
  CHECK(std::vector<std::uint8_t>(bytes, bytes + embedded->mWidth) == image->bytes);

  // Nodes: one per fragment, translated to its centroid; every corner where it was, with its attributes.
  std::vector<const aiNode*> nodes;
  for (unsigned i = 0; i < scene->mRootNode->mNumChildren; ++i) nodes.push_back(scene->mRootNode->mChildren[i]);
  if (nodes.empty()) nodes.push_back(scene->mRootNode);
  REQUIRE(nodes.size() == 2);
  for (std::size_t i = 0; i < 2; ++i) {
    const aiNode& node = *nodes[i];
    CHECK(std::string(node.mName.C_Str()) == "fragment_00" + std::to_string(i));
    const Vec3 centroid = fragments[i].mass.centroid;
    const aiMatrix4x4& m = node.mTransformation;
    CHECK(Vec3(m.a4, m.b4, m.c4).isApprox(centroid, 1e-6));
    CHECK(Vec3(m.a1, m.b2, m.c3) == Vec3(1, 1, 1));
    double area[2] = {0.0, 0.0};  // surface, interior
    for (unsigned k = 0; k < node.mNumMeshes; ++k) {
      const aiMesh& mesh = *scene->mMeshes[node.mMeshes[k]];
      REQUIRE(mesh.HasNormals());
      REQUIRE(mesh.HasTextureCoords(0));
      REQUIRE(mesh.HasTangentsAndBitangents());
      const bool interior = mesh.mMaterialIndex == material["interior"];
      for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        REQUIRE(mesh.mFaces[f].mNumIndices == 3);
        const unsigned* idx = mesh.mFaces[f].mIndices;
        const Vec3 p0 = vec(mesh.mVertices[idx[0]]) + centroid, p1 = vec(mesh.mVertices[idx[1]]) + centroid,
                   p2 = vec(mesh.mVertices[idx[2]]) + centroid;
        const Vec3 cross = (p1 - p0).cross(p2 - p0);
        area[interior ? 1 : 0] += 0.5 * cross.norm();
        // The interior faces are the cut plane x = 0; the surface faces are the box's others.
        if (interior) CHECK((std::abs(p0.x()) < 1e-6 && std::abs(p1.x()) < 1e-6 && std::abs(p2.x()) < 1e-6));
        for (int c = 0; c < 3; ++c) {
          const unsigned v = idx[c];
          const Vec3 p = vec(mesh.mVertices[v]) + centroid;
          // Positions on the boxes' corners (float precision), normals the outward face normal.
          CHECK(vec(mesh.mNormals[v]).isApprox(cross.normalized(), 1e-6));
          const Vec3 tangent = vec(mesh.mTangents[v]);
          CHECK(tangent.isApprox(cut_plane_basis(cross)[0], 1e-6));
          // UVs (the fixture's corners, cut faces included, carry the affine UV) in the attributes' v-up
          // convention after assimp's flip on import, i.e. written flipped as glTF wants.
          const Vec2 uv = uv_at(p);
          CHECK(mesh.mTextureCoords[0][v].x == Approx(uv.x()).margin(1e-6));
          CHECK(mesh.mTextureCoords[0][v].y == Approx(uv.y()).margin(1e-6));
        }
      }
    }
    // Surface area of a box minus its cut face; the cut face is y-z: 2 x 3.
    const Vec3 size = i == 0 ? Vec3(1, 2, 3) : Vec3(0.5, 2, 3);
    const double total = 2 * (size.x() * size.y() + size.y() * size.z() + size.z() * size.x());
    CHECK(area[1] == Approx(6.0).epsilon(1e-6));
    CHECK(area[0] == Approx(total - 6.0).epsilon(1e-6));
  }
}

TEST_CASE("glb writer: a fragment without attributes gets flat normals and the default material", "[assets][glb]") {
  const fs::path dir = fs::temp_directory_path() / "shatter_write_fragments_glb_plain";
  fs::create_directories(dir);
  Fragment plain;
  plain.mesh = make_box(Vec3(1, 1, 1), Vec3(3, 0, 0));
  plain.mass = mass_properties(plain.mesh);
  const std::vector<Fragment> fragments = {plain};
  REQUIRE(write_fragments_glb(dir / "plain.glb", fragments).ok());
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile((dir / "plain.glb").string(), 0);
  REQUIRE(scene != nullptr);
  REQUIRE(scene->mNumMeshes == 1);
  const aiMesh& mesh = *scene->mMeshes[0];
  REQUIRE(mesh.mNumFaces == 12);
  CHECK_FALSE(mesh.HasTextureCoords(0));
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const unsigned* idx = mesh.mFaces[f].mIndices;
    const Vec3 n = (vec(mesh.mVertices[idx[1]]) - vec(mesh.mVertices[idx[0]])).cross(vec(mesh.mVertices[idx[2]]) - vec(mesh.mVertices[idx[0]]));
    for (int c = 0; c < 3; ++c) CHECK(vec(mesh.mNormals[idx[c]]).isApprox(n.normalized(), 1e-6));
  }
}

TEST_CASE("glb writer: a fragment without attributes keeps its cut faces apart, in the interior material, and its volume",
          "[assets][glb]") {
  const fs::path dir = fs::temp_directory_path() / "shatter_write_fragments_glb_plain_cut";
  fs::create_directories(dir);
  Fragment plain;
  plain.mesh = make_box(Vec3(2, 1, 0.5), Vec3(3, 0, 0));  // volume 1 m^3: known without the writer
  int cut = 0;
  for (std::size_t f = 0; f < plain.mesh.triangles.size(); ++f) {
    const Triangle& t = plain.mesh.triangles[f];
    if (plain.mesh.vertices[t[0]].x() == 2.0 && plain.mesh.vertices[t[1]].x() == 2.0 && plain.mesh.vertices[t[2]].x() == 2.0) {
      plain.mesh.tags[f] = FaceTag::cut;
      ++cut;
    }
  }
  REQUIRE(cut == 2);
  plain.mass = mass_properties(plain.mesh);
  const std::vector<Fragment> fragments = {plain};
  REQUIRE(write_fragments_glb(dir / "plain.glb", fragments).ok());
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile((dir / "plain.glb").string(), 0);
  REQUIRE(scene != nullptr);
  REQUIRE(scene->mNumMeshes == 2);
  std::map<std::string, unsigned> faces_by_material;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    aiString name;
    scene->mMaterials[scene->mMeshes[m]->mMaterialIndex]->Get(AI_MATKEY_NAME, name);
    faces_by_material[name.C_Str()] += scene->mMeshes[m]->mNumFaces;
  }
  CHECK(faces_by_material["interior"] == 2);
  CHECK(faces_by_material.size() == 2);
  // The node's extras hold the volume, read back from the JSON chunk.
  std::ifstream in(dir / "plain.glb", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(bytes.size() > 20);
  std::uint32_t json_length = 0;
  std::memcpy(&json_length, bytes.data() + 12, 4);
  const nlohmann::json doc = nlohmann::json::parse(bytes.substr(20, json_length));
  CHECK(doc["nodes"][0]["extras"]["volume"].get<double>() == Approx(1.0).epsilon(1e-12));
}
