#pragma once
/// What the reader fuzzers demand of a mesh a reader returned: the Mesh invariants (one tag per
/// triangle, every index in range, attributes sized to the triangles, every value finite) or an abort,
/// which libFuzzer reports as a finding.

#include "algorithms/core/mesh.h"

#include <cmath>
#include <cstdlib>

namespace shatter::fuzz {

inline void abort_unless_valid(const Mesh& mesh) {
  if (mesh.tags.size() != mesh.triangles.size()) std::abort();
  for (const Triangle& t : mesh.triangles)
    for (const std::int32_t i : t)
      if (i < 0 || static_cast<std::size_t>(i) >= mesh.vertices.size()) std::abort();
  for (const Vec3& p : mesh.vertices)
    if (!p.allFinite()) std::abort();
  const MeshAttributes& a = mesh.attributes;
  if (a.corners.size() != 3 * mesh.triangles.size() * static_cast<std::size_t>(a.layout.stride())) std::abort();
  if (!a.materials.empty() && a.materials.size() != mesh.triangles.size()) std::abort();
  for (const std::int32_t m : a.materials)
    if (m < 0 || static_cast<std::size_t>(m) >= a.slots.size()) std::abort();
  for (const double v : a.corners)
    if (!std::isfinite(v)) std::abort();
}

}  // namespace shatter::fuzz
