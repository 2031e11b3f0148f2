#pragma once
/// A small seeded random generator whose output is the same on every platform and standard library
/// (std::uniform_real_distribution is not), so a seed names the same fracture everywhere.

#include "algorithms/core/mesh.h"

#include <cmath>
#include <cstdint>

namespace shatter {

/// SplitMix64 (Steele, Lea, Flood 2014): 64-bit state, full period, good enough for sampling planes.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  /// Next 64 random bits.
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform direction on the unit sphere (rejection from the cube).
  Vec3 unit_vector() {
    for (;;) {
      const Vec3 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      const double n2 = v.squaredNorm();
      if (n2 > 1e-4 && n2 <= 1.0) return v / std::sqrt(n2);
    }
  }
  /// Uniform point in the box [lo, hi].
  Vec3 point_in(const Vec3& lo, const Vec3& hi) {
    return {uniform(lo.x(), hi.x()), uniform(lo.y(), hi.y()), uniform(lo.z(), hi.z())};
  }

 private:
  std::uint64_t state_;
};

}  // namespace shatter
