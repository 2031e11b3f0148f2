#include "algorithms/fracture/fracture_output_check.h"

#include "algorithms/core/attribute_transfer.h"
#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_validation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <string>

namespace shatter {
namespace {

std::string num(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

/// The first defect of fragment `k` that makes its mesh unsafe or wrong to read, or "".
std::string mesh_defect(const Mesh& mesh) {
  if (mesh.tags.size() != mesh.triangles.size())
    return "holds " + std::to_string(mesh.tags.size()) + " face tags for " + std::to_string(mesh.triangles.size()) +
           " triangles";
  if (mesh.triangles.empty()) return "has no triangle";
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!mesh.vertices[v].allFinite()) return "vertex " + std::to_string(v) + " is not finite";
  const auto vertex_count = static_cast<std::int64_t>(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    for (const std::int32_t index : t)
      if (index < 0 || index >= vertex_count)
        return "triangle " + std::to_string(f) + " names vertex " + std::to_string(index) + " (the fragment has " +
               std::to_string(vertex_count) + ")";
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      return "triangle " + std::to_string(f) + " repeats a vertex";
    const auto tag = static_cast<unsigned>(mesh.tags[f]);
    if (tag > static_cast<unsigned>(FaceTag::repair))
      return "triangle " + std::to_string(f) + " has face tag " + std::to_string(tag) + " (known: 0 surface, 1 cut, 2 repair)";
  }
  if (!mesh.attributes.empty())
    if (Status s = check_attributes(mesh, "its attributes"); !s) return s.error().message;
  if (!is_closed_and_oriented(mesh)) return "is not closed and consistently oriented";
  return {};
}

}  // namespace

FractureOutputLimits limits_with_stated_tolerance(double stated) {
  FractureOutputLimits limits;
  if (std::isfinite(stated)) limits.max_volume_error = std::max(limits.max_volume_error, std::min(stated, kMaxStatedVolumeTolerance));
  return limits;
}

Status check_fracture_output(const Mesh& input, const std::vector<Fragment>& fragments, std::string_view algorithm,
                             const FractureOutputLimits& limits) {
  const std::string prefix = "fracturer '" + std::string(algorithm) + "' returned an invalid result: ";
  if (fragments.empty()) return Error{prefix + "no fragment"};
  if (fragments.size() > static_cast<std::size_t>(limits.max_fragments))
    return Error{prefix + std::to_string(fragments.size()) + " fragments, more than the limit of " +
                 std::to_string(limits.max_fragments)};
  const double input_volume = signed_volume(input);
  const double size = bounding_box(input).diagonal();
  // Scales of the mass comparison: the input's volume, size and inertia (V L^2), so that the test is
  // relative to the problem, not to a fragment that may be tiny.
  const double volume_scale = std::abs(input_volume);
  const double inertia_scale = volume_scale * size * size;
  double sum = 0.0;
  for (std::size_t k = 0; k < fragments.size(); ++k) {
    const Fragment& fragment = fragments[k];
    const std::string at = prefix + "fragment " + std::to_string(k) + " ";
    if (const std::string defect = mesh_defect(fragment.mesh); !defect.empty()) return Error{at + defect};
    const MassProperties m = mass_properties(fragment.mesh);
    if (!std::isfinite(m.volume) || !(m.volume > 0.0))
      return Error{at + "has volume " + num(m.volume) + ", not a finite positive number"};
    const MassProperties& stated = fragment.mass;
    const bool stated_finite = std::isfinite(stated.volume) && stated.centroid.allFinite() && stated.inertia.allFinite();
    if (!stated_finite) return Error{at + "states mass properties that are not finite"};
    const double tol = limits.max_mass_error;
    if (!(std::abs(stated.volume - m.volume) <= tol * volume_scale))
      return Error{at + "states volume " + num(stated.volume) + ", its mesh has " + num(m.volume)};
    if (!((stated.centroid - m.centroid).norm() <= tol * size))
      return Error{at + "states a centroid that is not its mesh's"};
    if (!((stated.inertia - m.inertia).norm() <= tol * inertia_scale))
      return Error{at + "states an inertia tensor that is not its mesh's"};
    sum += m.volume;
  }
  const double error = std::abs(sum - input_volume) / volume_scale;
  if (!(error <= limits.max_volume_error))
    return Error{prefix + "the fragments' volumes sum to " + num(sum) + ", the input's is " + num(input_volume) +
                 " (relative error " + num(error) + " > " + num(limits.max_volume_error) + ")"};
  return {};
}

}  // namespace shatter
