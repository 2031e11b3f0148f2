#pragma once
/// What the repair promises of its output, checked before it is returned.

#include "algorithms/core/mesh.h"

#include <optional>
#include <string>

namespace shatter::repair {

/// Why `mesh` is not a solid the fracturers accept, or nothing: the acceptance rule (validate_solid,
/// on a copy) with cavities allowed (inward shells nested inside outward ones, shell_classification.h),
/// and no self-intersection (find_self_intersection).
std::optional<std::string> solid_defect(const Mesh& mesh);

}  // namespace shatter::repair
