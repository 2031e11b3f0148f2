#pragma once
/// FNV-1a (64 bit): the hash of the results' fingerprints and of the history's ids. Not for secrets.

#include <cstdint>
#include <string_view>

namespace shatter {

/// FNV-1a's offset basis: the hash of no bytes.
inline constexpr std::uint64_t kFnv1aBasis = 0xcbf29ce484222325ULL;

/// `hash` continued over the bytes of `text`.
inline std::uint64_t fnv1a(std::string_view text, std::uint64_t hash = kFnv1aBasis) {
  for (unsigned char byte : text) hash = (hash ^ byte) * 0x100000001b3ULL;
  return hash;
}

/// `hash` continued over `field` and a 0x1f separator, so that fields cannot run into each other.
inline std::uint64_t fnv1a_field(std::string_view field, std::uint64_t hash) { return fnv1a("\x1f", fnv1a(field, hash)); }

}  // namespace shatter
