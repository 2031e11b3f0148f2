#include "algorithms/core/solid_check.h"

#include "algorithms/core/edge_classification.h"
#include "algorithms/core/mesh_fingerprint.h"
#include "algorithms/core/representable_range.h"
#include "algorithms/core/self_intersection.h"
#include "algorithms/core/shell_classification.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace shatter {
namespace {

/// The first violation of the rule except self-intersection, or an empty string.
std::string first_violation(const Mesh& mesh) {
  if (mesh.triangles.empty() || mesh.vertices.empty()) return "empty mesh (no triangles)";
  if (mesh.tags.size() != mesh.triangles.size())
    return std::to_string(mesh.tags.size()) + " face tags for " + std::to_string(mesh.triangles.size()) + " triangles";
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!within_coordinate_range(mesh.vertices[v])) {
      std::ostringstream s;
      s << "vertex " << v << " (" << mesh.vertices[v].x() << ", " << mesh.vertices[v].y() << ", "
        << mesh.vertices[v].z() << ") is "
        << (mesh.vertices[v].allFinite() ? "outside the representable range +-1e9 m" : "not finite");
      return s.str();
    }
  const auto vertex_count = static_cast<std::int64_t>(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (const std::int32_t index : mesh.triangles[f])
      if (index < 0 || index >= vertex_count)
        return "triangle " + std::to_string(f) + " has vertex index " + std::to_string(index) + " out of range (" +
               std::to_string(vertex_count) + " vertices)";
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return "triangle " + std::to_string(f) + " is degenerate (repeated vertex)";
    if (exactly_collinear(mesh.vertices[static_cast<std::size_t>(t[0])], mesh.vertices[static_cast<std::size_t>(t[1])],
                          mesh.vertices[static_cast<std::size_t>(t[2])]))
      return "triangle " + std::to_string(f) + " has zero area (collinear corners)";
  }

  // The first bad edge in triangle order: holes before non-manifold edges before orientation.
  const EdgeClassification edges = classify_edges(mesh.triangles, mesh.vertices.size());
  for (const EdgeState wanted : {EdgeState::open, EdgeState::non_manifold, EdgeState::misoriented}) {
    const auto bad = std::find(edges.state.begin(), edges.state.end(), wanted);
    if (bad == edges.state.end()) continue;
    const auto e = static_cast<std::size_t>(bad - edges.state.begin());
    const Triangle& t = mesh.triangles[e / 3];
    const std::int32_t a = t[e % 3], b = t[(e % 3 + 1) % 3];
    const std::string edge = "edge (" + std::to_string(std::min(a, b)) + ", " + std::to_string(std::max(a, b)) + ")";
    if (wanted == EdgeState::open) return "not closed: " + edge + " is used by 1 triangle";
    if (wanted == EdgeState::non_manifold)
      return "not 2-manifold: " + edge + " is used by " + std::to_string(edges.uses[e]) + " triangles";
    return "inconsistent orientation at " + edge;
  }

  // A closed shell whose volume rounds to nothing relative to the mesh's size is flat.
  const ShellClassification shells = classify_shells(mesh);
  const double size = bounding_box(mesh).diagonal();
  for (int s = 0; s < static_cast<int>(shells.shells.size()); ++s)
    if (std::abs(shells.shells[static_cast<std::size_t>(s)].volume) <= 1e-14 * size * size * size)
      return shells.shells.size() == 1 ? "zero volume (flat closed mesh)" : "zero volume: " + shell_name(shells, s) + " is flat";
  if (shells.verdict == SolidVerdict::invalid) return shells.reason;
  if (shells.inverted) return "faces inward (negative volume): every outermost shell is oriented inside out";
  return {};
}

}  // namespace

Status check_solid(const Mesh& mesh, std::string_view who, SelfIntersectionVerdicts* verdicts) {
  const std::uint64_t fingerprint = verdicts != nullptr ? mesh_fingerprint(mesh) : 0;
  if (verdicts != nullptr && verdicts->remembers(fingerprint)) return {};
  if (std::string violation = first_violation(mesh); !violation.empty())
    return Error{std::string(who) + ": " + violation};
  if (const auto pair = find_self_intersection(mesh))
    return Error{std::string(who) + ": the input mesh intersects itself (triangles " + std::to_string((*pair)[0]) +
                 " and " + std::to_string((*pair)[1]) + ")"};
  if (verdicts != nullptr) verdicts->remember(fingerprint);
  return {};
}

}  // namespace shatter
