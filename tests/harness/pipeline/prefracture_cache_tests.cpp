#include "harness/pipeline/prefracture_cache.h"

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/mass_properties.h"
#include "algorithms/core/primitives.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

using namespace shatter;
namespace fs = std::filesystem;

namespace {

/// A box with every attribute channel (values that are not short decimals), two material slots of
/// which one has `image`, prepared for cut faces.
Mesh attributed_box(const Vec3& center, const std::shared_ptr<const TextureImage>& image) {
  Mesh mesh = make_box(Vec3(1.0 / 3.0, 0.7, 1.1), center);
  MeshAttributes& a = mesh.attributes;
  a.layout = AttributeLayout{true, 2, true};
  MaterialSlot wood, paint;
  wood.name = "wood";
  wood.base_color = {0.1, 0.2, 1.0 / 3.0, 0.9};
  wood.base_color_image = image;
  paint.name = "paint";
  paint.base_color_texture = "paint.png";
  a.slots = {wood, paint};
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    a.materials.push_back(static_cast<std::int32_t>(f % 2));
    for (int k = 0; k < 3; ++k) {
      const double s = 0.1 * static_cast<double>(3 * f + static_cast<std::size_t>(k)) + 1.0 / 7.0;
      a.corners.insert(a.corners.end(), {std::sin(s), std::cos(s), 0.0, s / 3.0, 1.0 - s, s * s, -s, std::cos(s),
                                         -std::sin(s), 0.0, k == 1 ? -1.0 : 1.0});
    }
  }
  prepare_cut_faces(mesh, 0.3);
  return mesh;
}

}  // namespace

TEST_CASE("prefracture cache: attributed fragments come back bit for bit, images shared", "[pipeline][cache]") {
  const fs::path folder = fs::temp_directory_path() / "shatter_prefracture_cache_attributes";
  fs::remove_all(folder);
  auto image = std::make_shared<TextureImage>();
  image->mime_type = "image/png";
  image->bytes = {0x89, 'P', 'N', 'G', 0, 255, 7};
  const Mesh solid = attributed_box(Vec3(0, 0, 0), image);
  std::vector<Fragment> fragments(2);
  fragments[0].mesh = attributed_box(Vec3(-1, 0, 0), image);
  fragments[1].mesh = attributed_box(Vec3(1, 0, 0), image);
  for (Fragment& f : fragments) f.mass = mass_properties(f.mesh);
  const PrefractureCache cache(folder);
  PrefractureKey key;
  key.fracturer = "plane-slice";
  key.fragments = 2;
  REQUIRE(cache.store(solid, key, fragments));
  const std::optional<std::vector<Fragment>> back = cache.load(solid, key);
  REQUIRE(back.has_value());
  REQUIRE(back->size() == 2);
  for (std::size_t i = 0; i < 2; ++i) {
    const MeshAttributes& got = (*back)[i].mesh.attributes;
    const MeshAttributes& want = fragments[i].mesh.attributes;
    CHECK((*back)[i].mesh.vertices == fragments[i].mesh.vertices);
    CHECK(got.layout == want.layout);
    CHECK(got.corners == want.corners);  // exact: raw doubles
    CHECK(got.materials == want.materials);
    CHECK(got.cut == want.cut);
    REQUIRE(got.slots.size() == want.slots.size());
    for (std::size_t s = 0; s < got.slots.size(); ++s) {
      CHECK(got.slots[s].name == want.slots[s].name);
      CHECK(got.slots[s].base_color == want.slots[s].base_color);
      CHECK(got.slots[s].base_color_texture == want.slots[s].base_color_texture);
      CHECK(static_cast<bool>(got.slots[s].base_color_image) == static_cast<bool>(want.slots[s].base_color_image));
    }
    REQUIRE(got.slots[0].base_color_image);
    CHECK(got.slots[0].base_color_image->bytes == image->bytes);
    CHECK(got.slots[0].base_color_image->mime_type == image->mime_type);
  }
  // One image in the file, shared again by both fragments.
  CHECK((*back)[0].mesh.attributes.slots[0].base_color_image == (*back)[1].mesh.attributes.slots[0].base_color_image);
  // The solid's attributes are part of the key: another UV layout is another entry.
  Mesh retextured = solid;
  retextured.attributes.corners[3] += 0.5;
  CHECK_FALSE(cache.load(retextured, key).has_value());
  fs::remove_all(folder);
}
