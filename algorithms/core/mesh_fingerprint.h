#pragma once
/// A 64-bit fingerprint of a mesh's exact contents, to recognise a mesh seen before.

#include "algorithms/core/mesh.h"

#include <cstdint>

namespace shatter {

/// Hash of the counts and the exact bytes of the vertex and triangle arrays (8 bytes per round of a
/// multiply-rotate mix, about 20 us for a 10k-triangle mesh). Equal meshes give equal fingerprints; a
/// change of one bit anywhere changes it but with probability about 2^-64. Not a cryptographic hash:
/// meant for meshes, not for an adversary.
std::uint64_t mesh_fingerprint(const Mesh& mesh);

}  // namespace shatter
