#include "algorithms/repair/solid_check.h"

#include "algorithms/core/mesh_validation.h"

namespace shatter::repair {

std::optional<std::string> solid_defect(const Mesh& mesh) {
  Mesh copy = mesh;
  Result<ValidationReport> valid = validate_solid(copy, "the repaired mesh");
  if (!valid) return valid.error().message;
  if (valid->flipped) return std::string("the repaired mesh faces inward");
  return std::nullopt;
}

}  // namespace shatter::repair
