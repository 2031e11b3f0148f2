#include "algorithms/core/mesh_fingerprint.h"

#include <bit>
#include <cstddef>
#include <cstring>

namespace shatter {
namespace {

constexpr std::uint64_t kPrime1 = 0x9E3779B185EBCA87ull;
constexpr std::uint64_t kPrime2 = 0xC2B2AE3D27D4EB4Full;

/// One round of the mix (the round of xxHash64).
std::uint64_t mix(std::uint64_t h, std::uint64_t word) { return std::rotl(h ^ (word * kPrime2), 31) * kPrime1; }

/// Mixes `size` bytes at `data` into `h`, 8 at a time, the tail zero-padded.
std::uint64_t mix_bytes(std::uint64_t h, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::size_t at = 0;
  for (; at + 8 <= size; at += 8) {
    std::uint64_t word;
    std::memcpy(&word, bytes + at, 8);
    h = mix(h, word);
  }
  if (at < size) {
    std::uint64_t word = 0;
    std::memcpy(&word, bytes + at, size - at);
    h = mix(h, word);
  }
  return h;
}

}  // namespace

std::uint64_t mesh_fingerprint(const Mesh& mesh) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Triangle) == 3 * sizeof(std::int32_t));
  std::uint64_t h = mix(kPrime2, mesh.vertices.size());
  h = mix(h, mesh.triangles.size());
  h = mix_bytes(h, mesh.vertices.data(), mesh.vertices.size() * sizeof(Vec3));
  h = mix_bytes(h, mesh.triangles.data(), mesh.triangles.size() * sizeof(Triangle));
  // Final avalanche, so that close inputs end far apart in every bit.
  h ^= h >> 33;
  h *= kPrime2;
  h ^= h >> 29;
  return h;
}

}  // namespace shatter
