// The case file's `appearance`: a generated mesh dressed as a textured asset, the interior material
// and the cut-face UV scale reaching the solid, and every bad value one error line naming the key.

#include "algorithms/core/attribute_transfer.h"
#include "harness/cases/case_loader.h"
#include "harness/cases/case_mesh.h"

#include <catch2/catch.hpp>

#include <string>

#ifndef SHATTER_SOURCE_DIR
#error "tests need SHATTER_SOURCE_DIR (a compile definition of the test target)"
#endif

using namespace shatter;

namespace {

Result<Case> parse(const std::string& text) { return parse_case(text, "cases/appearance.json"); }

void require_error(const std::string& text, const std::string& part) {
  const Result<Case> c = parse(text);
  INFO(text);
  REQUIRE_FALSE(c.ok());
  INFO(c.error().message);
  CHECK(c.error().message.find('\n') == std::string::npos);
  CHECK_THAT(c.error().message, Catch::StartsWith("cases/appearance.json: ") && Catch::Contains(part));
}

}  // namespace

TEST_CASE("appearance: a dressed box carries box-mapped attributes, the case's interior material and cut-face scale",
          "[cases][attributes]") {
  const Result<Case> c = parse(R"({"mesh": {"box": {"size": [2, 1, 1]}},
    "appearance": {"surface": {"name": "brick", "base_color": [0.6, 0.3, 0.2, 1]}, "uv_scale": 0.5,
                   "interior": {"name": "mortar", "base_color": [0.8, 0.8, 0.75, 1]}, "cap_uv_scale": 0.25}})");
  REQUIRE(c.ok());
  Result<Solid> solid = build_case_solid(*c);
  REQUIRE(solid.ok());
  const MeshAttributes& a = solid->mesh.attributes;
  REQUIRE(check_attributes(solid->mesh, "solid").ok());
  CHECK(a.layout == AttributeLayout{.normals = true, .uv_sets = 1, .tangents = true});
  REQUIRE(a.slots.size() == 2);
  CHECK(a.slots[0].name == "brick");
  CHECK(a.slots[0].base_color == std::array<double, 4>{0.6, 0.3, 0.2, 1.0});
  CHECK(a.slots[1].name == "mortar");
  CHECK(a.cut.material == 1);
  CHECK(a.cut.uv_scale == 0.25);
  // The +x face (x = 1): u = y / 0.5, v = z / 0.5.
  for (std::size_t f = 0; f < solid->mesh.triangles.size(); ++f) {
    const double* n = a.corner(f, 0);
    if (n[0] != 1.0) continue;
    const Vec3& p = solid->mesh.vertices[static_cast<std::size_t>(solid->mesh.triangles[f][0])];
    CHECK(n[3] == Approx(p.y() / 0.5));
    CHECK(n[4] == Approx(p.z() / 0.5));
  }
  // --cap-uv-scale overrides the case's scale.
  Case overridden = *c;
  set_cap_uv_scale(overridden, 3.0);
  Result<Solid> again = build_case_solid(overridden);
  REQUIRE(again.ok());
  CHECK(again->mesh.attributes.cut.uv_scale == 3.0);
}

TEST_CASE("appearance: a case without it has a solid without attributes", "[cases][attributes]") {
  const Result<Case> c = parse(R"({"mesh": {"box": {"size": [1, 1, 1]}}})");
  REQUIRE(c.ok());
  Result<Solid> solid = build_case_solid(*c);
  REQUIRE(solid.ok());
  CHECK(solid->mesh.attributes.empty());
}

TEST_CASE("appearance: bad values are one error line naming the key", "[cases][attributes]") {
  const std::string box = R"("mesh": {"box": {"size": [1, 1, 1]}})";
  require_error("{" + box + R"(, "appearance": {"surface": {"name": "a", "base_color": [1, 0, 0]}}})",
                "appearance.surface.base_color");
  require_error("{" + box + R"(, "appearance": {"surface": {"name": "a", "base_color": [1, 0, 2, 1]}}})",
                "appearance.surface.base_color[2]");
  require_error("{" + box + R"(, "appearance": {"surface": {"base_color": [1, 0, 0, 1]}}})", "appearance.surface.name");
  require_error("{" + box + R"(, "appearance": {"surface": {"name": ""}}})", "appearance.surface.name");
  require_error("{" + box + R"(, "appearance": {"uv_scale": 0}})", "appearance.uv_scale");
  require_error("{" + box + R"(, "appearance": {"cap_uv_scale": -1}})", "appearance.cap_uv_scale");
  require_error("{" + box + R"(, "appearance": {"colour": 1}})", "colour");
  require_error("{" + box + R"(, "appearance": {"surface": {"name": "x"}, "interior": {"name": "x"}}})",
                "appearance.interior.name");
  const std::string file = std::string(SHATTER_SOURCE_DIR) + "/data/meshes/elephant.off";
  require_error(R"({"mesh": {"file": ")" + file + R"("}, "appearance": {"surface": {"name": "x"}}})",
                "appearance.surface");
}
