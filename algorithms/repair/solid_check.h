#pragma once
/// What the repair promises of its output, checked before it is returned.

#include "algorithms/core/mesh.h"

#include <optional>
#include <string>

namespace shatter::repair {

/// Why `mesh` is not a solid the fracturers accept, or nothing: the acceptance rule (validate_solid on
/// a copy: check_solid after normalising, so cavities allowed and self-intersections refused), and the
/// mesh facing outward as it is.
std::optional<std::string> solid_defect(const Mesh& mesh);

}  // namespace shatter::repair
