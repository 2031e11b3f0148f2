#include "harness/cases/case_loader.h"

#include "algorithms/core/bounded_read.h"
#include "algorithms/fracture/fracture_limits.h"
#include "harness/cases/case_mesh.h"
#include "harness/cases/json_reader.h"
#include "harness/cases/physical_range.h"
#include "harness/cases/plugin_settings_json.h"
#include "harness/limits.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

namespace shatter {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

/// Reads a one-line string (no line breaks); `non_empty` refuses "".
void read_line(JsonReader& r, const json& obj, std::string_view key, bool non_empty, std::string& out) {
  if (!r.read(obj, "", key, out)) return;
  if (out.find_first_of("\r\n") != std::string::npos) r.fail(key, "must be one line");
  if (non_empty && out.empty()) r.fail(key, "must not be empty");
}

/// Reads a fragment count: an integer in [1, kMaxFragments].
void read_fragments(JsonReader& r, const json& obj, std::string_view path, std::string_view key, int& out) {
  if (!r.read(obj, path, key, out)) return;
  const std::string at = key_path(path, key);
  r.at_least(at, out, 1) && r.at_most(at, out, kMaxFragments);
}

/// Reads a registered-algorithm name (kept as a string; the caller checks it against its registry).
void read_name(JsonReader& r, const json& obj, std::string_view path, std::string_view key, std::string& out) {
  if (r.read(obj, path, key, out) && out.empty()) r.fail(key_path(path, key), "must not be empty");
}

Material read_material(JsonReader& r, const json& v) {
  Material m;
  if (!r.object(v, "material", {"density", "young_modulus", "poisson_ratio", "tensile_strength",
                                "compressive_strength", "shear_strength"}))
    return m;
  read_in_range(r, v, "material", "density", m.density, kDensityRange);
  read_in_range(r, v, "material", "young_modulus", m.young_modulus, kYoungModulusRange);
  read_in_range(r, v, "material", "poisson_ratio", m.poisson_ratio, kPoissonRatioRange);
  read_in_range(r, v, "material", "tensile_strength", m.tensile_strength, kStrengthRange);
  read_in_range(r, v, "material", "compressive_strength", m.compressive_strength, kStrengthRange);
  read_in_range(r, v, "material", "shear_strength", m.shear_strength, kStrengthRange);
  return m;
}

/// A render material: `{"name": ..., "base_color": [r, g, b, a]}`, name required, colour in [0, 1].
MaterialSlot read_render_material(JsonReader& r, const json& v, std::string_view at) {
  MaterialSlot m;
  if (!r.object(v, at, {"name", "base_color"})) return m;
  if (r.read_required(v, at, "name", m.name) &&
      (m.name.empty() || m.name.find_first_of("\r\n") != std::string::npos))
    r.fail(key_path(at, "name"), "must be one non-empty line");
  if (!v.contains("base_color")) return m;
  const json& color = v["base_color"];
  const std::string color_at = key_path(at, "base_color");
  if (!r.array(color, color_at)) return m;
  if (color.size() != 4) {
    r.fail(color_at, "must hold 4 numbers (r, g, b, a)");
    return m;
  }
  for (std::size_t i = 0; i < 4 && !r.failed(); ++i) {
    const std::string item = index_path(color_at, i);
    if (r.convert(color[i], item, m.base_color[i]) && !(m.base_color[i] >= 0.0 && m.base_color[i] <= 1.0))
      r.fail(item, "must be in [0, 1]");
  }
  return m;
}

AppearanceSpec read_appearance(JsonReader& r, const json& v) {
  AppearanceSpec a;
  if (!r.object(v, "appearance", {"surface", "uv_scale", "interior", "cap_uv_scale"})) return a;
  if (v.contains("surface")) a.surface = read_render_material(r, v["surface"], "appearance.surface");
  if (v.contains("interior")) a.interior = read_render_material(r, v["interior"], "appearance.interior");
  read_in_range(r, v, "appearance", "uv_scale", a.uv_scale, kLengthRange);
  read_in_range(r, v, "appearance", "cap_uv_scale", a.cap_uv_scale, kLengthRange);
  if (!r.failed() && a.surface && a.surface->name == (a.interior ? a.interior->name : std::string("interior")))
    r.fail("appearance.interior.name", "must differ from the surface material's name");
  return a;
}

std::vector<Aabb> read_anchors(JsonReader& r, const json& v) {
  std::vector<Aabb> anchors;
  if (!r.array(v, "anchors")) return anchors;
  for (std::size_t i = 0; i < v.size() && !r.failed(); ++i) {
    const std::string at = index_path("anchors", i);
    if (!r.object(v[i], at, {"box"})) break;
    const std::string box_at = key_path(at, "box");
    if (!v[i].contains("box")) {
      r.fail(box_at, "missing required key");
      break;
    }
    const json& box = v[i]["box"];
    Aabb a;
    if (!r.object(box, box_at, {"min", "max"})) break;
    read_required_in_range(r, box, box_at, "min", a.min, kCoordinateRange);
    read_required_in_range(r, box, box_at, "max", a.max, kCoordinateRange);
    if (!r.failed() && !(a.min.array() <= a.max.array()).all())
      r.fail(box_at, fmt::format("min must be <= max on every axis, got min [{}] max [{}]",
                                 fmt::join(a.min, ", "), fmt::join(a.max, ", ")));
    anchors.push_back(a);
  }
  return anchors;
}

PrefractureSpec read_prefracture(JsonReader& r, const json& v) {
  PrefractureSpec p;
  if (!r.object(v, "prefracture", {"fracturer", "fragments", "seed", "settings", "planes"})) return p;
  if (v.contains("planes")) {
    for (const char* key : {"fracturer", "fragments", "seed", "settings"})
      if (v.contains(key)) {
        r.fail("prefracture", fmt::format("\"{}\" and \"planes\" are exclusive: give one", key));
        return p;
      }
    const json& planes = v["planes"];
    if (!r.array(planes, "prefracture.planes")) return p;
    if (planes.empty()) r.fail("prefracture.planes", "must list at least one plane");
    if (planes.size() > static_cast<std::size_t>(kMaxExplicitPlanes))
      r.fail("prefracture.planes",
             fmt::format("{} planes exceed the limit of {} planes", planes.size(), kMaxExplicitPlanes));
    for (std::size_t i = 0; i < planes.size() && !r.failed(); ++i) {
      const std::string at = index_path("prefracture.planes", i);
      Plane plane;
      if (!r.object(planes[i], at, {"point", "normal"})) break;
      read_required_in_range(r, planes[i], at, "point", plane.point, kCoordinateRange);
      if (r.read_required(planes[i], at, "normal", plane.normal)) r.non_zero(key_path(at, "normal"), plane.normal);
      p.planes.push_back(plane);
    }
    return p;
  }
  read_name(r, v, "prefracture", "fracturer", p.fracturer);
  read_fragments(r, v, "prefracture", "fragments", p.fragments);
  r.read(v, "prefracture", "seed", p.seed);
  read_plugin_settings(r, v, "prefracture", p.settings);
  return p;
}

/// Unit vector along `v` (non-zero, finite), safe against underflow of tiny components.
Vec3 unit(const Vec3& v) {
  const Vec3 scaled = v / v.cwiseAbs().maxCoeff();
  return scaled.normalized();
}

std::vector<ImpactEvent> read_impacts(JsonReader& r, const json& v, int frames) {
  std::vector<ImpactEvent> impacts;
  if (!r.array(v, "impacts")) return impacts;
  if (v.size() > static_cast<std::size_t>(kMaxImpacts))
    r.fail("impacts", fmt::format("{} impacts exceed the limit of {} impacts per case", v.size(), kMaxImpacts));
  for (std::size_t i = 0; i < v.size() && !r.failed(); ++i) {
    const std::string at = index_path("impacts", i);
    const json& item = v[i];
    ImpactEvent e;
    if (!r.object(item, at, {"frame", "point", "direction", "impulse", "radius"})) break;
    if (r.read_required(item, at, "frame", e.frame)) {
      r.at_least(key_path(at, "frame"), e.frame, 0) && r.at_most(key_path(at, "frame"), e.frame, frames - 1);
    }
    read_required_in_range(r, item, at, "point", e.impact.point, kCoordinateRange);
    if (r.read_required(item, at, "direction", e.impact.direction) &&
        r.non_zero(key_path(at, "direction"), e.impact.direction))
      e.impact.direction = unit(e.impact.direction);
    read_required_in_range(r, item, at, "impulse", e.impact.impulse, kImpulseRange);
    read_in_range(r, item, at, "radius", e.impact.radius, kImpactRadiusRange);
    impacts.push_back(e);
  }
  return impacts;
}

RuntimeSpec read_runtime(JsonReader& r, const json& v) {
  RuntimeSpec s;
  if (!r.object(v, "runtime", {"fracturer", "fragments", "settings"})) return s;
  read_name(r, v, "runtime", "fracturer", s.fracturer);
  read_fragments(r, v, "runtime", "fragments", s.fragments);
  read_plugin_settings(r, v, "runtime", s.settings);
  return s;
}

StressSpec read_stress(JsonReader& r, const json& v) {
  StressSpec s;
  if (!r.object(v, "stress", {"model", "settings"})) return s;
  read_name(r, v, "stress", "model", s.model);
  read_plugin_settings(r, v, "stress", s.settings);
  return s;
}

/// Reads a non-empty list of distinct fragment counts.
void read_counts(JsonReader& r, const json& obj, std::string_view key, std::vector<int>& out) {
  const std::string at = key_path("grid", key);
  if (!obj.contains(key) || !r.array(obj[std::string(key)], at)) return;
  const json& list = obj[std::string(key)];
  if (list.empty()) r.fail(at, "must list at least one count");
  std::vector<int> counts;
  for (std::size_t i = 0; i < list.size() && !r.failed(); ++i) {
    int n = 0;
    const std::string item = index_path(at, i);
    if (!r.convert(list[i], item, n) || !r.at_least(item, n, 1) || !r.at_most(item, n, kMaxFragments)) break;
    if (std::find(counts.begin(), counts.end(), n) != counts.end()) r.fail(item, fmt::format("duplicate count {}", n));
    counts.push_back(n);
  }
  if (!r.failed()) out = counts;
}

GridSpec read_grid(JsonReader& r, const json& v) {
  GridSpec g;
  if (!r.object(v, "grid", {"prefracture", "runtime"})) return g;
  read_counts(r, v, "prefracture", g.prefracture);
  read_counts(r, v, "runtime", g.runtime);
  if (r.failed()) return g;
  const auto cells = static_cast<std::int64_t>(g.prefracture.size()) * static_cast<std::int64_t>(g.runtime.size());
  if (cells > kMaxGridCells)
    r.fail("grid", fmt::format("{} x {} = {} cells exceed the limit of {} cells per grid", g.prefracture.size(),
                               g.runtime.size(), cells, kMaxGridCells));
  const std::int64_t p = *std::max_element(g.prefracture.begin(), g.prefracture.end());
  const std::int64_t q = *std::max_element(g.runtime.begin(), g.runtime.end());
  if (p * q > kMaxRunPieces)
    r.fail("grid", fmt::format("cell {} x {} can make {} runtime pieces, which exceeds the limit of {} pieces per run",
                               p, q, p * q, kMaxRunPieces));
  return g;
}

Needs read_needs(JsonReader& r, const json& v) {
  Needs needs{false, false, false, false, false};
  if (!r.array(v, "needs")) return Needs{};
  if (v.empty()) r.fail("needs", fmt::format("must list at least one of {}", fmt::join(need_names, ", ")));
  std::set<std::string> seen;
  for (std::size_t i = 0; i < v.size() && !r.failed(); ++i) {
    const std::string at = index_path("needs", i);
    std::string name;
    if (!r.convert(v[i], at, name)) break;
    if (!seen.insert(name).second) r.fail(at, fmt::format("duplicate \"{}\"", name));
    bool* flag = name == "fragments" ? &needs.fragments
                 : name == "bonds"   ? &needs.bonds
                 : name == "stress"  ? &needs.stress
                 : name == "colliders" ? &needs.colliders
                 : name == "physics" ? &needs.physics
                                     : nullptr;
    if (flag == nullptr)
      r.fail(at, fmt::format("unknown need \"{}\" (allowed: {})", name, fmt::join(need_names, ", ")));
    else
      *flag = true;
  }
  return needs;
}

ScheduleSpec read_schedule(JsonReader& r, const json& v) {
  ScheduleSpec s;
  if (!r.object(v, "schedule", {"mode", "prefetch_frames", "work_budget_ms", "max_new_bodies_per_frame"})) return s;
  std::string mode;
  if (r.read(v, "schedule", "mode", mode)) {
    if (const auto m = schedule_mode_from_name(mode))
      s.mode = *m;
    else
      r.fail("schedule.mode", fmt::format("unknown mode \"{}\" (allowed: immediate, prefetch, amortized)", mode));
  }
  if (r.read(v, "schedule", "prefetch_frames", s.prefetch_frames)) r.at_least("schedule.prefetch_frames", s.prefetch_frames, 0);
  if (r.read(v, "schedule", "work_budget_ms", s.work_budget_ms)) r.non_negative("schedule.work_budget_ms", s.work_budget_ms);
  if (r.read(v, "schedule", "max_new_bodies_per_frame", s.max_new_bodies_per_frame))
    r.at_least("schedule.max_new_bodies_per_frame", s.max_new_bodies_per_frame, 0);
  return s;
}

FadeOutSpec read_fade_out(JsonReader& r, const json& v) {
  FadeOutSpec f;
  if (!r.object(v, "fade_out", {"volume", "lifetime_frames"})) return f;
  f.enabled = true;
  if (r.read_required(v, "fade_out", "volume", f.max_volume)) r.non_negative("fade_out.volume", f.max_volume);
  if (r.read(v, "fade_out", "lifetime_frames", f.lifetime_frames)) r.at_least("fade_out.lifetime_frames", f.lifetime_frames, 1);
  return f;
}

DebrisSpec read_debris(JsonReader& r, const json& v) {
  DebrisSpec d;
  if (!r.object(v, "debris", {"per_area", "per_impact", "speed", "lifetime_frames"})) return d;
  d.enabled = true;
  if (r.read(v, "debris", "per_area", d.per_area)) r.non_negative("debris.per_area", d.per_area);
  if (r.read(v, "debris", "per_impact", d.per_impact))
    r.at_least("debris.per_impact", d.per_impact, 0) &&
        r.at_most("debris.per_impact", d.per_impact, kMaxDebrisPerEvent);
  read_in_range(r, v, "debris", "speed", d.speed, kDebrisSpeedRange);
  if (r.read(v, "debris", "lifetime_frames", d.lifetime_frames)) r.at_least("debris.lifetime_frames", d.lifetime_frames, 1);
  return d;
}

CollidersSpec read_colliders(JsonReader& r, const json& v) {
  CollidersSpec c;
  if (!r.object(v, "colliders", {"vertex_budget"})) return c;
  if (r.read(v, "colliders", "vertex_budget", c.vertex_budget) && c.vertex_budget != 0)
    r.at_least("colliders.vertex_budget", c.vertex_budget, 4) && r.at_most("colliders.vertex_budget", c.vertex_budget, 256);
  return c;
}

}  // namespace

std::string_view schedule_mode_name(ScheduleMode mode) {
  switch (mode) {
    case ScheduleMode::immediate: return "immediate";
    case ScheduleMode::prefetch: return "prefetch";
    case ScheduleMode::amortized: return "amortized";
  }
  return "immediate";
}

Status check_case_name(const std::string& name) {
  // The name becomes a file name (the baseline results/baselines/<name>.json, report images): it must
  // stay one, in the folder it is written to.
  if (name.empty()) return Error{"must not be empty"};
  if (name.size() > kMaxCaseNameBytes)
    return Error{fmt::format("{} bytes exceed the limit of {} bytes per case name", name.size(), kMaxCaseNameBytes)};
  if (name.front() == '.') return Error{"must not start with '.' (the name is a file name)"};
  if (name.find("..") != std::string::npos) return Error{"must not contain \"..\" (the name is a file name)"};
  for (const char ch : name) {
    const auto u = static_cast<unsigned char>(ch);
    if (ch == '/' || ch == '\\') return Error{"must not contain '/' or '\\' (the name is a file name)"};
    if (u < 0x20 || u == 0x7f) return Error{"must not contain control characters (the name is a file name)"};
  }
  return {};
}

std::optional<ScheduleMode> schedule_mode_from_name(std::string_view name) {
  for (const ScheduleMode m : {ScheduleMode::immediate, ScheduleMode::prefetch, ScheduleMode::amortized})
    if (schedule_mode_name(m) == name) return m;
  return std::nullopt;
}

namespace {

Result<Case> parse_case_text(std::string_view text, const fs::path& source) {
  const std::string file = source.empty() ? std::string("<case>") : source.string();
  Result<json> parsed = parse_json(text, file);
  if (!parsed) return parsed.error();
  const json& root = *parsed;
  JsonReader r(file);
  if (!r.object(root, "", {"name", "description", "mesh", "material", "gravity", "anchors", "prefracture",
                           "appearance", "impacts", "runtime", "stress", "frames", "budget_ms", "grid", "needs", "schedule", "fade_out", "debris", "colliders"}))
    return r.error();

  Case c;
  c.source = source;
  c.name = source.empty() ? std::string("case") : source.stem().string();
  read_line(r, root, "name", true, c.name);
  if (Status s = check_case_name(c.name); !s) r.fail("name", s.error().message);
  read_line(r, root, "description", false, c.description);
  if (!root.contains("mesh"))
    r.fail("mesh", "missing required key");
  else
    c.mesh = read_mesh_spec(r, root["mesh"], "mesh", source.parent_path());
  if (root.contains("material")) c.material = read_material(r, root["material"]);
  if (root.contains("appearance")) c.appearance = read_appearance(r, root["appearance"]);
  if (!r.failed() && c.appearance.surface && std::holds_alternative<MeshFileSpec>(c.mesh))
    r.fail("appearance.surface", "a mesh file brings its own attributes; surface dresses generated meshes only");
  read_in_range(r, root, "", "gravity", c.gravity, kGravityComponentRange);
  if (root.contains("anchors")) c.anchors = read_anchors(r, root["anchors"]);
  if (root.contains("prefracture")) c.prefracture = read_prefracture(r, root["prefracture"]);
  if (r.read(root, "", "frames", c.frames))
    r.at_least("frames", c.frames, 1) && r.at_most("frames", c.frames, kMaxFrames);
  if (root.contains("impacts")) c.impacts = read_impacts(r, root["impacts"], c.frames);
  if (root.contains("runtime")) c.runtime = read_runtime(r, root["runtime"]);
  if (root.contains("stress")) c.stress = read_stress(r, root["stress"]);
  if (r.read(root, "", "budget_ms", c.budget_ms)) r.positive("budget_ms", c.budget_ms);
  if (root.contains("grid")) c.grid = read_grid(r, root["grid"]);
  if (root.contains("needs")) c.needs = read_needs(r, root["needs"]);
  if (root.contains("schedule")) c.schedule = read_schedule(r, root["schedule"]);
  if (root.contains("fade_out")) c.fade_out = read_fade_out(r, root["fade_out"]);
  if (root.contains("colliders")) c.colliders = read_colliders(r, root["colliders"]);
  if (root.contains("debris")) c.debris = read_debris(r, root["debris"]);
  if (r.failed()) return r.error();
  return c;
}

}  // namespace

Result<Case> parse_case(std::string_view text, const fs::path& source) {
  Result<Case> c = parse_case_text(text, source);
  // Messages quote keys and values of the file: keep them on one line whatever those hold.
  if (!c) return Error{escape_control_characters(c.error().message)};
  return c;
}

Result<Case> load_case(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return Error{fmt::format("{}: case file not found", path.string())};
  const Result<std::string> text = read_file_bounded(path, kMaxCaseFileBytes, "case file");
  if (!text) return Error{escape_control_characters(text.error().message)};
  return parse_case(*text, path);
}

}  // namespace shatter
