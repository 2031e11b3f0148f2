// The offline setup shared by the destruction run and the case structure: the same structure either
// way, the cache read and filled, bonds on request, anchor regions checked.

#include "tests/support/builtin_registries.h"
#include "harness/cases/case_library.h"
#include "harness/cases/case_mesh.h"
#include "harness/pipeline/case_structure.h"
#include "harness/pipeline/setup/offline_structure.h"
#include "harness/plugins/capable_fracturer.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <unistd.h>

namespace {

using namespace shatter;

struct Fixture {
  Case spec;
  Solid solid;
  std::unique_ptr<Fracturer> fracturer;
};

Fixture fixture(const std::string& name) {
  Result<Case> c = find_case(name);
  REQUIRE(c);
  Result<Solid> solid = build_case_solid(*c);
  REQUIRE(solid);
  Fixture f{std::move(*c), std::move(*solid), nullptr};
  const Registries r = test::builtin_registries();
  auto fracturer = f.spec.prefracture.explicit_planes() ? plane_cutter(r.fracturers, f.spec.prefracture.fracturer)
                                                        : r.fracturers.create(f.spec.prefracture.fracturer);
  REQUIRE(fracturer);
  f.fracturer = std::move(*fracturer);
  return f;
}

OfflineSetupRequest request_for(const Fixture& f) {
  OfflineSetupRequest r;
  r.fracturer = f.fracturer.get();
  r.fragments = f.spec.prefracture.fragments;
  r.seed = f.spec.prefracture.seed;
  return r;
}

bool same_fragments(const std::vector<Fragment>& a, const std::vector<Fragment>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].mesh.vertices != b[i].mesh.vertices || a[i].mesh.triangles != b[i].mesh.triangles) return false;
  return true;
}

bool skipped(const StageLog& log, const std::string& stage, const std::string& words) {
  return std::any_of(log.skips().begin(), log.skips().end(), [&](const StageSkip& s) {
    return s.stage == stage && s.reason.find(words) != std::string::npos;
  });
}

}  // namespace

TEST_CASE("offline setup: the case structure is the run's structure at the case's settings", "[pipeline][setup]") {
  const std::string name = GENERATE(as<std::string>{}, "cantilever", "building");  // explicit planes, a fracturer
  INFO(name);
  const Fixture f = fixture(name);
  StageClocks clocks;
  StageLog log;
  Result<OfflineStructure> s = build_offline_structure(f.spec, f.solid, request_for(f), clocks, log);
  REQUIRE(s);
  Result<CaseStructure> cs = build_case_structure(f.spec, test::builtin_registries());
  REQUIRE(cs);
  REQUIRE(same_fragments(s->fragments, cs->fragments));
  REQUIRE(s->graph.bond_count() == cs->graph.bond_count());
  REQUIRE(s->graph.bond_count() > 0);
  REQUIRE(s->key.fragments == (f.spec.prefracture.explicit_planes() ? 0 : f.spec.prefracture.fragments));
  REQUIRE(s->key.fracturer == (f.spec.prefracture.explicit_planes() ? "plane-slice" : f.spec.prefracture.fracturer));
  REQUIRE(s->anchored.size() == s->fragments.size());
  REQUIRE(std::count(s->anchored.begin(), s->anchored.end(), std::uint8_t{1}) >= 1);
  const auto ran = log.run();
  REQUIRE(ran == std::vector<std::string>{"prefracture", "bonds"});
  REQUIRE(clocks.wall[static_cast<std::size_t>(Stage::prefracture)] > 0.0);
}

TEST_CASE("offline setup: bonds only on request, an anchor region that touches nothing is an error",
          "[pipeline][setup]") {
  Fixture f = fixture("cantilever");
  OfflineSetupRequest request = request_for(f);
  request.bonds = false;
  StageClocks clocks;
  StageLog log;
  Result<OfflineStructure> s = build_offline_structure(f.spec, f.solid, request, clocks, log);
  REQUIRE(s);
  REQUIRE(s->graph.bond_count() == 0);
  REQUIRE(skipped(log, "bonds", "not needed"));

  f.spec.anchors.push_back(Aabb{Vec3(50, 50, 50), Vec3(51, 51, 51)});
  const std::string index = std::to_string(f.spec.anchors.size() - 1);
  Result<OfflineStructure> bad = build_offline_structure(f.spec, f.solid, request_for(f), clocks, log);
  REQUIRE_FALSE(bad);
  REQUIRE(bad.error().message.find("anchors[" + index + "]") != std::string::npos);
}

TEST_CASE("offline setup: the cache is filled, then read bit for bit, and skipped when reading is off",
          "[pipeline][setup]") {
  const auto folder =
      std::filesystem::temp_directory_path() / ("shatter_offline_cache_" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  const PrefractureCache cache(folder);
  const Fixture f = fixture("building");
  OfflineSetupRequest request = request_for(f);
  request.cache = &cache;
  StageClocks clocks;
  StageLog first_log;
  Result<OfflineStructure> first = build_offline_structure(f.spec, f.solid, request, clocks, first_log);
  REQUIRE(first);
  REQUIRE_FALSE(first->cache_hit);
  StageLog second_log;
  Result<OfflineStructure> second = build_offline_structure(f.spec, f.solid, request, clocks, second_log);
  REQUIRE(second);
  REQUIRE(second->cache_hit);
  REQUIRE(skipped(second_log, "prefracture", "taken from the cache"));
  REQUIRE(same_fragments(first->fragments, second->fragments));
  request.read_cache = false;
  StageLog third_log;
  Result<OfflineStructure> third = build_offline_structure(f.spec, f.solid, request, clocks, third_log);
  REQUIRE(third);
  REQUIRE_FALSE(third->cache_hit);
  std::filesystem::remove_all(folder);
}
