#include "algorithms/stress/strength_criterion.h"

#include <algorithm>
#include <cmath>

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
  const double flexural = bending(forces.moment_1, bond.fibre_1, bond.moment_1) +
                          bending(forces.moment_2, bond.fibre_2, bond.moment_2);
  const double tension_fibre = axial + flexural;
  const double compression_fibre = axial - flexural;
  s.tensile = std::abs(tension_fibre) >= std::abs(compression_fibre) && tension_fibre > 0.0;
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
