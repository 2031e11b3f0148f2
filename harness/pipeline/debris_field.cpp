#include "harness/pipeline/debris_field.h"

#include "algorithms/core/mass_properties.h"
#include "harness/limits.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace shatter {

DebrisField::DebrisField(const DebrisSpec& spec, const Vec3& gravity, double ground_z)
    : spec_(spec), gravity_(gravity), ground_z_(ground_z) {}

int DebrisField::count_for(double cut_area_m2) const {
  // Clamped in double before the conversion: per_area x area has no bound of its own.
  const double n = std::round(spec_.per_area * std::max(0.0, cut_area_m2)) + spec_.per_impact;
  return static_cast<int>(std::min(n, static_cast<double>(kMaxDebrisPerEvent)));
}

int DebrisField::spawn(int count, const std::vector<Vec3>& origins, std::uint64_t seed) {
  count = std::min(count, kMaxDebrisParticles - size());
  if (count <= 0 || origins.empty()) return 0;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < count; ++i) {
    // Uniform on the upper hemisphere: z = u, azimuth uniform.
    const double z = unit(rng);
    const double phi = 2.0 * std::numbers::pi * unit(rng);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    position_.push_back(origins[static_cast<std::size_t>(i) % origins.size()]);
    velocity_.push_back(spec_.speed * Vec3(r * std::cos(phi), r * std::sin(phi), z));
    age_.push_back(0);
  }
  return count;
}

void DebrisField::step(double dt) {
  constexpr double kGroundFriction = 0.9;  // velocity kept per frame while sliding on the ground
  std::size_t i = 0;
  while (i < position_.size()) {
    velocity_[i] += gravity_ * dt;
    position_[i] += velocity_[i] * dt;
    if (position_[i].z() < ground_z_) {
      position_[i].z() = ground_z_;
      velocity_[i].z() = 0.0;
      velocity_[i] *= kGroundFriction;
    }
    if (++age_[i] >= spec_.lifetime_frames) {
      position_[i] = position_.back();
      velocity_[i] = velocity_.back();
      age_[i] = age_.back();
      position_.pop_back();
      velocity_.pop_back();
      age_.pop_back();
    } else {
      ++i;
    }
  }
}

double new_cut_area(const Fragment& parent, const std::vector<Fragment>& pieces) {
  double sum = 0.0;
  for (const Fragment& p : pieces) sum += surface_area(p.mesh);
  return std::max(0.0, 0.5 * (sum - surface_area(parent.mesh)));
}

}  // namespace shatter
