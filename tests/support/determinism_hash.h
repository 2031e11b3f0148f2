#pragma once
/// Determinism hashes: a stable 64-bit digest of what an algorithm produced, compared against the
/// digests committed in tests/fixtures/determinism_hashes.json.
///
/// Design note: a digest is FNV-1a 64 over a defined byte serialisation, never std::hash (which may
/// differ between standard libraries and runs). Every value goes in as little-endian bytes: integers as
/// 64-bit two's complement, doubles as their exact IEEE-754 bit pattern (so one ulp anywhere changes the
/// digest), booleans and face tags as one byte; every sequence is preceded by its length. A changed
/// digest is a change of behaviour: regenerate the file only when the change is intended and say why
/// in the commit:
///     SHATTER_WRITE_DETERMINISM_HASHES=1 build/bin/shatter_tests "[determinism]"

#include "algorithms/core/mesh.h"
#include "algorithms/fracture/fracturer.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <vector>

#ifndef SHATTER_SOURCE_DIR
#error "tests need SHATTER_SOURCE_DIR (a compile definition of the test target)"
#endif

namespace shatter::test {

/// FNV-1a 64 over the byte serialisation described in the file comment.
class DeterminismHash {
 public:
  /// One byte.
  void add_byte(std::uint8_t b) {
    state_ ^= b;
    state_ *= 0x100000001b3ULL;
  }
  /// A 64-bit unsigned integer, little-endian.
  void add_u64(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) add_byte(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  /// A signed integer, as 64-bit two's complement.
  void add_int(std::int64_t v) { add_u64(static_cast<std::uint64_t>(v)); }
  /// A double, by its exact bit pattern.
  void add_double(double v) { add_u64(std::bit_cast<std::uint64_t>(v)); }
  /// A boolean, one byte (0 or 1).
  void add_bool(bool v) { add_byte(v ? 1 : 0); }
  /// A sequence of integers, length first.
  void add_ints(std::span<const int> v) {
    add_int(static_cast<std::int64_t>(v.size()));
    for (const int x : v) add_int(x);
  }
  /// A mesh: vertex count and positions (x, y, z), triangle count and indices, tag count and tags.
  void add_mesh(const Mesh& m) {
    add_int(static_cast<std::int64_t>(m.vertices.size()));
    for (const Vec3& v : m.vertices) {
      add_double(v.x());
      add_double(v.y());
      add_double(v.z());
    }
    add_int(static_cast<std::int64_t>(m.triangles.size()));
    for (const Triangle& t : m.triangles) {
      add_int(t[0]);
      add_int(t[1]);
      add_int(t[2]);
    }
    add_int(static_cast<std::int64_t>(m.tags.size()));
    for (const FaceTag tag : m.tags) add_byte(static_cast<std::uint8_t>(tag));
  }
  /// Fragments in order: count, then each fragment's mesh.
  void add_fragments(const std::vector<Fragment>& fragments) {
    add_int(static_cast<std::int64_t>(fragments.size()));
    for (const Fragment& f : fragments) add_mesh(f.mesh);
  }
  /// The digest as 16 lower-case hex digits.
  [[nodiscard]] std::string hex() const {
    static constexpr char digits[] = "0123456789abcdef";
    std::string s(16, '0');
    for (int i = 0; i < 16; ++i) s[static_cast<std::size_t>(15 - i)] = digits[(state_ >> (4 * i)) & 0xf];
    return s;
  }

 private:
  std::uint64_t state_ = 0xcbf29ce484222325ULL;  // FNV-1a 64 offset basis
};

/// The committed digests: one JSON object from key to 16 hex digits.
inline std::filesystem::path determinism_hashes_path() {
  return std::filesystem::path(SHATTER_SOURCE_DIR) / "tests" / "fixtures" / "determinism_hashes.json";
}

/// True when SHATTER_WRITE_DETERMINISM_HASHES is set: digests are written, not compared.
inline bool writing_determinism_hashes() {
  const char* env = std::getenv("SHATTER_WRITE_DETERMINISM_HASHES");
  return env != nullptr && *env != '\0' && std::string(env) != "0";
}

/// Compares `digest` with the committed digest of `key` (fails, saying how to regenerate, when they
/// differ or the key is missing); in writing mode stores it in the file instead.
inline void check_determinism_hash(const std::string& key, const DeterminismHash& digest) {
  const std::filesystem::path path = determinism_hashes_path();
  nlohmann::ordered_json hashes = nlohmann::ordered_json::object();
  if (std::ifstream in(path); in) hashes = nlohmann::ordered_json::parse(in);
  if (writing_determinism_hashes()) {
    hashes[key] = digest.hex();
    std::ofstream out(path);
    out << hashes.dump(2) << '\n';
    REQUIRE(out.good());
    return;
  }
  INFO("determinism hash of \"" << key << "\" (" << path.string() << ")");
  INFO("a different hash is a change of behaviour: explain it, and only then regenerate with "
       "SHATTER_WRITE_DETERMINISM_HASHES=1 build/bin/shatter_tests \"[determinism]\"");
  REQUIRE(hashes.contains(key));
  CHECK(hashes[key].get<std::string>() == digest.hex());
}

}  // namespace shatter::test
