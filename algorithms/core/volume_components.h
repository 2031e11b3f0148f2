#pragma once
/// Volumes of a closed solid: what a fracturer calls one fragment.
///
/// Design note: a solid is one or more volumes; a volume is an outer (outward) shell plus the inward
/// shells of the cavities inside it. A cut through a hollow solid leaves pieces whose connected parts
/// include cavity shells; a cavity shell on its own is no fragment (it has negative volume), it belongs
/// to the outer shell around it. An outward shell inside a cavity (an island) is a volume of its own.
/// Cost: connected_components, plus, only when some part faces inward, one winding-number query per
/// inward part against each outward part whose box holds it.

#include "algorithms/core/mesh.h"

#include <vector>

namespace shatter {

/// Splits the closed, consistently oriented `mesh`, whose shells neither cross nor nest with one
/// orientation, into its volumes: each an outward shell with the inward shells directly inside it,
/// in the order of the outward shells' first triangles (connected_components' order), each volume's
/// outer shell first and then its cavities. An inward shell inside no outward one stays a part of its own
/// (the caller's acceptance rule refuses it). A mesh without inward shells gives connected_components.
std::vector<Mesh> volume_components(const Mesh& mesh);

/// Same, consuming the mesh.
std::vector<Mesh> volume_components(Mesh&& mesh);

}  // namespace shatter
