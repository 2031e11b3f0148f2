#include "algorithms/stress/strength_criterion.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shatter {

double equivalent_stress(Criterion criterion, double sigma, double tau) {
  const double factor = criterion == Criterion::tresca ? 4.0 : 3.0;
  return std::sqrt(sigma * sigma + factor * tau * tau);
}

BondStress bond_stress(const Bond& bond, const BondForces& forces, const Material& material, Criterion criterion) {
  BondStress s;
  s.normal_force = forces.normal;
  s.shear_force = std::hypot(forces.shear_1, forces.shear_2);
  s.bending_moment = std::hypot(forces.moment_1, forces.moment_2);
  s.torsion = std::abs(forces.torsion);
  if (!(bond.area > 0.0)) return s;  // a degenerate bond carries nothing (never built by the graph)

  // An axis with no second moment (a line contact) contributes no bending stress rather than Inf.
  auto bending = [](double moment, double fibre, double inertia) {
    return inertia > 0.0 ? std::abs(moment) * fibre / inertia : 0.0;
  };
  const double axial = forces.normal / bond.area;
  double tension_fibre = 0.0;
  double compression_fibre = 0.0;
  if (!bond.section.empty() && bond.moment_1 > 0.0 && bond.moment_2 > 0.0) {
    // The traction sigma(p) = N/A + (M_1/I_1) p_2 - (M_2/I_2) p_1 is linear over the section, so its
    // extremes are at hull vertices (p_1 along axis_1, p_2 along axis_2, from the centroid).
    const double k1 = forces.moment_1 / bond.moment_1;
    const double k2 = -forces.moment_2 / bond.moment_2;
    double hi = -std::numeric_limits<double>::infinity();
    double lo = std::numeric_limits<double>::infinity();
    for (const Vec2& p : bond.section) {
      const double b = k1 * p.y() + k2 * p.x();
      hi = std::max(hi, b);
      lo = std::min(lo, b);
    }
    tension_fibre = axial + std::max(hi, 0.0);
    compression_fibre = axial + std::min(lo, 0.0);
  } else {
    const double flexural = bending(forces.moment_1, bond.fibre_1, bond.moment_1) +
                            bending(forces.moment_2, bond.fibre_2, bond.moment_2);
    tension_fibre = axial + flexural;
    compression_fibre = axial - flexural;
  }
  // In pure bending both fibres carry the same stress, and the solve leaves their difference at
  // round-off (an axial force of ~1e-12 N against 1e5 Pa of bending): which one governs is decided to
  // a relative kFibreTie, and a tie goes to tension (a brittle material fails in tension first).
  constexpr double kFibreTie = 1e-9;
  s.tensile = tension_fibre > 0.0 && std::abs(tension_fibre) >= (1.0 - kFibreTie) * std::abs(compression_fibre);
  s.sigma = std::max(std::abs(tension_fibre), std::abs(compression_fibre));
  s.tau = s.shear_force / bond.area +
          (bond.polar_moment > 0.0 ? s.torsion * bond.radius / bond.polar_moment : 0.0);

  double utilization = s.tau / material.shear_strength;
  if (tension_fibre > 0.0)
    utilization = std::max(utilization, equivalent_stress(criterion, tension_fibre, s.tau) / material.tensile_strength);
  if (compression_fibre < 0.0)
    utilization =
        std::max(utilization, equivalent_stress(criterion, compression_fibre, s.tau) / material.compressive_strength);
  s.utilization = utilization;
  return s;
}

}  // namespace shatter
