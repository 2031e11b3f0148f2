#include "harness/stability/fracture_hazards.h"

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_assembly.h"
#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/primitives.h"
#include "harness/metrics/fracture_metrics.h"
#include "harness/plugins/capable_fracturer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace shatter {
namespace {

Plane plane(const Vec3& point, const Vec3& normal) { return Plane{point, normal}; }

/// The cube [-0.5, 0.5]^3 with vertex i at (x, y, z) = bits (0, 1, 2) of i; 12 outward triangles.
Mesh explicit_cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.add_vertex(Vec3((i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5));
  const Triangle tris[] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                           {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (const Triangle& t : tris) m.add_triangle(t[0], t[1], t[2], FaceTag::surface);
  return m;
}

/// The cube with a cap triangle: a vertex 1e-9 below the middle of the top edge of the +y face.
Mesh cube_with_cap() {
  Mesh m = explicit_cube();
  const std::int32_t v = m.add_vertex(Vec3(0.0, 0.5, 0.5 - 1e-9));
  // The +y face's triangle (2, 6, 7) becomes (2, 6, v), (2, v, 7) and the cap (6, 7, v).
  for (std::size_t i = 0; i < m.triangles.size(); ++i)
    if (m.triangles[i] == Triangle{2, 6, 7}) m.triangles[i] = Triangle{2, 6, v};
  m.add_triangle(2, v, 7, FaceTag::surface);
  m.add_triangle(6, 7, v, FaceTag::surface);
  return m;
}

Mesh scaled(Mesh m, double factor, const Vec3& offset = Vec3::Zero()) {
  for (Vec3& p : m.vertices) p = p * factor + offset;
  return m;
}

/// Two unit cubes touching at one corner, the origin: closed, but pinched there.
Mesh pinched_cubes() {
  Mesh a = make_box(Vec3(1, 1, 1), Vec3(-0.5, -0.5, -0.5));
  append_mesh(a, make_box(Vec3(1, 1, 1), Vec3(0.5, 0.5, 0.5)));
  return a;
}

FractureHazard hazard(std::string name, std::string description, Mesh mesh, std::vector<Plane> planes,
                      int fragments = 8) {
  FractureHazard h;
  h.name = std::move(name);
  h.description = std::move(description);
  h.mesh = std::move(mesh);
  h.planes = std::move(planes);
  h.params.fragments = fragments;
  h.params.seed = 7;
  return h;
}

bool same_fragments(const std::vector<Fragment>& a, const std::vector<Fragment>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Mesh& x = a[i].mesh;
    const Mesh& y = b[i].mesh;
    if (x.triangles != y.triangles || x.tags != y.tags || x.vertices.size() != y.vertices.size()) return false;
    if (!x.vertices.empty() &&
        std::memcmp(x.vertices.data(), y.vertices.data(), x.vertices.size() * sizeof(Vec3)) != 0)
      return false;
  }
  return true;
}

Result<std::vector<Fragment>> fracture_each(const Fracturer& f, const std::vector<Fragment>& pieces,
                                            const FractureParams& params) {
  std::vector<Fragment> out;
  for (const Fragment& piece : pieces) {
    Result<std::vector<Fragment>> parts = f.fracture(piece.mesh, params);
    if (!parts) return parts.error();
    for (Fragment& part : *parts) out.push_back(std::move(part));
  }
  return out;
}

/// `h` run by `f` on `solid`. Exact planes are cut by `f` when it cuts by given planes; else `cutter`
/// (a fracturer that does, chosen by run_fracture_hazard) cuts them and `f` fractures every piece.
Result<std::vector<Fragment>> run_once(const FractureHazard& h, const Fracturer& f, const Fracturer* cutter,
                                       const Mesh& solid) {
  if (!h.planes.empty()) {
    if (const PlaneCutting* own = f.plane_cutting()) return own->cut_by_planes(solid, h.planes);
    Result<std::vector<Fragment>> pieces = cutter->plane_cutting()->cut_by_planes(solid, h.planes);
    if (!pieces) return pieces.error();
    return fracture_each(f, *pieces, h.params);
  }
  Result<std::vector<Fragment>> fragments = f.fracture(solid, h.params);
  if (!fragments || !h.refracture) return fragments;
  return fracture_each(f, *fragments, h.params);
}

/// The first failed per-fragment check, or "".
std::string fragment_check(const std::vector<Fragment>& fragments) {
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    const Fragment& f = fragments[i];
    const std::string which = "fragment " + std::to_string(i);
    if (f.mesh.empty()) return which + " is empty";
    if (f.mesh.tags.size() != f.mesh.triangles.size()) return which + ": tag count differs from triangle count";
    if (!all_finite(f.mesh)) return which + ": NaN or Inf coordinate";
    if (!std::isfinite(f.mass.volume) || !f.mass.centroid.allFinite() || !f.mass.inertia.allFinite())
      return which + ": NaN or Inf mass property";
    if (!is_closed_and_oriented(f.mesh)) return which + ": not closed and oriented";
  }
  return {};
}

}  // namespace

std::vector<FractureHazard> fracture_hazards(bool quick) {
  const Mesh cube = explicit_cube();
  const double tilt = 1e-9;  // rad
  std::vector<FractureHazard> out;
  out.push_back(hazard("cut-through-vertices", "cube cut by x+y+z=-0.5 through three corners", cube,
                       {plane(Vec3(0.5, 0.5, -0.5), Vec3(1, 1, 1))}));
  out.push_back(hazard("cut-along-edges", "cube cut by the diagonal plane holding two vertical edges", cube,
                       {plane(Vec3::Zero(), Vec3(1, -1, 0))}));
  out.push_back(hazard("cut-containing-faces", "cube cut by the plane of a face, then twice by x=0", cube,
                       {plane(Vec3(0.5, 0, 0), Vec3::UnitX()), plane(Vec3::Zero(), Vec3::UnitX()),
                        plane(Vec3::Zero(), Vec3::UnitX())}));
  out.push_back(hazard("nearly-parallel-planes", "cube cut by z=0, by a plane 1e-9 rad from it, and by z=1e-9",
                       cube,
                       {plane(Vec3::Zero(), Vec3::UnitZ()), plane(Vec3::Zero(), Vec3(std::sin(tilt), 0, std::cos(tilt))),
                        plane(Vec3(0, 0, 1e-9), Vec3::UnitZ())}));
  out.push_back(hazard("grazing-planes", "cube cut 1e-12 inside its top face and its -x face", cube,
                       {plane(Vec3(0, 0, 0.5 - 1e-12), Vec3::UnitZ()), plane(Vec3(-0.5 + 1e-12, 0, 0), Vec3::UnitX())}));
  const Mesh sphere = make_sphere(1.0, 16, 8);
  out.push_back(hazard("scale-1e-4", "sphere of radius 1e-4 m, 8 fragments", scaled(sphere, 1e-4), {}));
  out.push_back(hazard("scale-1e4", "sphere of radius 1e4 m, 8 fragments", scaled(sphere, 1e4), {}));
  out.push_back(hazard("translated-1e6", "unit sphere centred at (1e6, 1e6, 1e6), 8 fragments",
                       scaled(sphere, 1.0, Vec3(1e6, 1e6, 1e6)), {}));
  out.push_back(hazard("needle-triangles", "cylinder of radius 1e-3 and length 1 (64 needle sides), 8 fragments",
                       make_cylinder(1e-3, 1.0, 64), {}));
  out.push_back(hazard("cap-triangles", "cube with a cap triangle (a vertex 1e-9 off an edge), 8 fragments",
                       cube_with_cap(), {}));
  out.push_back(hazard("thin-plate", "plate 1 x 1 x 1e-6 m, 8 fragments", make_box(Vec3(1, 1, 1e-6)), {}));
  const int deep = quick ? 100 : 1000;
  out.push_back(hazard("deep-recursion", "sphere into " + std::to_string(deep) + " fragments", sphere, {}, deep));
  out.back().may_refuse = true;  // cgal-clip states a limit of 250 fragments
  FractureHazard again = hazard("refracture", "cube into 8 fragments, each fractured into 8 again", cube, {});
  again.refracture = true;
  out.push_back(std::move(again));
  out.push_back(hazard("inverted-orientation", "cube with every triangle reversed", reversed_mesh(cube), {}));
  out.push_back(hazard("duplicated-vertices", "cube as a triangle soup (36 vertices)", triangle_soup(cube), {}));
  out.push_back(hazard("pinched-vertex", "two cubes sharing one corner (non-manifold vertex)", pinched_cubes(), {}));
  out.back().may_refuse = true;
  return out;
}

HazardResult run_fracture_hazard(const FractureHazard& h, const std::string& algorithm,
                                 const Registries& registries, const FractureCheckLimits& limits) {
  HazardResult r;
  r.hazard = h.name;
  r.algorithm = algorithm;
  r.kind = "fracture";
  Result<std::unique_ptr<Fracturer>> fracturer = registries.fracturers.create(algorithm);
  if (!fracturer) {
    r.outcome = refusal_outcome(fracturer.error());
    r.detail = fracturer.error().message;
    return r;
  }
  Mesh solid = h.mesh;
  if (Result<ValidationReport> report = validate_solid(solid, h.name); !report) {
    r.outcome = HazardOutcome::rejected_input;
    r.detail = report.error().message;
    return r;
  }
  // The exact cut for a fracturer that cannot cut by given planes: made by one that can.
  std::unique_ptr<Fracturer> cutter;
  if (!h.planes.empty() && (*fracturer)->plane_cutting() == nullptr) {
    Result<std::unique_ptr<Fracturer>> chosen = plane_cutter(registries.fracturers);
    if (!chosen) {
      r.outcome = HazardOutcome::refused_valid_input;
      r.detail = chosen.error().message;
      return r;
    }
    cutter = std::move(*chosen);
  }
  Result<std::vector<Fragment>> first = run_once(h, **fracturer, cutter.get(), solid);
  if (!first) {
    r.outcome = refusal_outcome(first.error());
    if (r.outcome == HazardOutcome::rejected_input && !h.may_refuse) r.outcome = HazardOutcome::refused_valid_input;
    r.detail = first.error().message;
    return r;
  }
  r.fragments = static_cast<int>(first->size());
  r.outcome = HazardOutcome::invalid_output;
  if (first->empty()) {
    r.detail = "no fragment";
    return r;
  }
  if (std::string failed = fragment_check(*first); !failed.empty()) {
    r.detail = failed;
    return r;
  }
  FractureMetricsOptions options;
  options.partition_samples = limits.partition_samples;
  const FractureMetrics m = fracture_metrics(solid, mass_properties(solid), *first, h.params.fragments, options);
  r.worst_error = std::max(m.volume_error, m.partition_error);
  if (!m.all_closed) {  // the shell rule every solid passes (fracture_metrics.h)
    r.detail = m.fragment_problem;
    return r;
  }
  if (!(m.volume_error <= limits.volume_error)) {
    r.detail = "volume error " + std::to_string(m.volume_error);
    return r;
  }
  if (!(m.partition_error <= limits.partition_error)) {
    r.detail = "partition error " + std::to_string(m.partition_error);
    return r;
  }
  Result<std::vector<Fragment>> second = run_once(h, **fracturer, cutter.get(), solid);
  if (!second || !same_fragments(*first, *second)) {
    r.detail = "not deterministic: a second run gave different fragments";
    return r;
  }
  r.outcome = HazardOutcome::valid;
  return r;
}

}  // namespace shatter
