#pragma once
/// Whether a triangulated cap closes the outline it was built on: the cap's half-edges, less one copy
/// of every outline edge, pair up with their twins. Then the piece the cap is glued to (the outline's
/// side of the solid) is closed along the cap. Shared by the plane slicer and the Voronoi cell clipper.

#include "algorithms/core/mesh.h"
#include "algorithms/core/cap_triangulator.h"

#include <absl/container/flat_hash_map.h>

#include <cstdint>
#include <span>

namespace shatter {

/// Scratch counts of directed half-edges, kept by the caller so that repeated checks reuse its memory.
using HalfEdgeCounts = absl::flat_hash_map<std::uint64_t, int>;

/// True when `cap` (triangles over the outline's point indices) closes `outline` (directed edges).
/// `counts` is cleared and used as scratch.
bool cap_closes_outline(std::span<const Triangle> cap, std::span<const CapEdge> outline, HalfEdgeCounts& counts);

}  // namespace shatter
