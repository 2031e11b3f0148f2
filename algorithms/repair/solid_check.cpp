#include "algorithms/repair/solid_check.h"

#include "algorithms/core/mesh_validation.h"
#include "algorithms/core/self_intersection.h"
#include "algorithms/core/shell_classification.h"

#include <cmath>

namespace shatter::repair {

std::optional<std::string> solid_defect(const Mesh& mesh) {
  Mesh copy = mesh;
  Result<ValidationReport> valid = validate_solid(copy, "the repaired mesh");
  if (!valid) {
    // A solid with cavities fails validate_solid only at its shell verdict; accept exactly that.
    if (!is_closed_and_oriented(copy)) return valid.error().message;
    const ShellClassification shells = classify_shells(copy);
    if (shells.verdict != SolidVerdict::with_cavities || shells.inverted) return valid.error().message;
    const double size = bounding_box(copy).diagonal();
    for (const Shell& shell : shells.shells)
      if (std::abs(shell.volume) <= 1e-14 * size * size * size) return valid.error().message;
  }
  if (valid && valid->flipped) return std::string("the repaired mesh faces inward");
  if (const auto pair = find_self_intersection(copy))
    return "the repaired mesh intersects itself (triangles " + std::to_string((*pair)[0]) + " and " +
           std::to_string((*pair)[1]) + ")";
  return std::nullopt;
}

}  // namespace shatter::repair
