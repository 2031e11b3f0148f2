#include "algorithms/core/volume_components.h"

#include "algorithms/core/mass_properties.h"
#include "algorithms/core/mesh_assembly.h"
#include "algorithms/core/mesh_components.h"
#include "algorithms/core/winding_number.h"

#include <cmath>
#include <optional>

namespace shatter {
namespace {


std::vector<Mesh> group(std::vector<Mesh>&& parts) {
  if (parts.size() < 2) return std::move(parts);
  std::vector<double> volume(parts.size());
  bool any_inward = false;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    volume[i] = signed_volume(parts[i]);
    any_inward = any_inward || volume[i] < 0.0;
  }
  if (!any_inward) return std::move(parts);

  // Each inward part joins the smallest outward part that holds a point of it (the centroid of its
  // first triangle: on no other shell, since shells do not cross).
  std::vector<std::optional<WindingNumberQuery>> inside(parts.size());
  std::vector<std::int32_t> owner(parts.size(), -1);
  std::vector<Aabb> box(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) box[i] = bounding_box(parts[i]);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (volume[i] >= 0.0) continue;
    const Triangle& t = parts[i].triangles.front();
    const Vec3 point = (parts[i].vertices[static_cast<std::size_t>(t[0])] + parts[i].vertices[static_cast<std::size_t>(t[1])] +
                        parts[i].vertices[static_cast<std::size_t>(t[2])]) /
                       3.0;
    for (std::size_t j = 0; j < parts.size(); ++j) {
      if (volume[j] <= 0.0 || !box[j].contains(point)) continue;
      if (owner[i] >= 0 && volume[j] >= volume[static_cast<std::size_t>(owner[i])]) continue;
      if (!inside[j]) inside[j].emplace(parts[j]);
      if (std::abs((*inside[j])(point)) > 0.5) owner[i] = static_cast<std::int32_t>(j);
    }
  }
  std::vector<Mesh> volumes;
  std::vector<std::int32_t> volume_of(parts.size(), -1);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (owner[i] >= 0) continue;
    volume_of[i] = static_cast<std::int32_t>(volumes.size());
    volumes.push_back(std::move(parts[i]));
  }
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (owner[i] >= 0) append_mesh(volumes[static_cast<std::size_t>(volume_of[static_cast<std::size_t>(owner[i])])], parts[i]);
  return volumes;
}

}  // namespace

std::vector<Mesh> volume_components(const Mesh& mesh) { return group(connected_components(mesh)); }

std::vector<Mesh> volume_components(Mesh&& mesh) { return group(connected_components(std::move(mesh))); }

}  // namespace shatter
