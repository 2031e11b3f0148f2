#pragma once
/// From a bond's internal forces to its peak stresses and its utilization under Tresca or von Mises.
///
/// Peak normal stress (beam theory over the contact section, principal axes 1 and 2): the traction
///   sigma(p) = N / A + (M_1 / I_1) p_2 - (M_2 / I_2) p_1        (N > 0 in tension)
/// is linear over the section, so its largest and smallest values are at vertices of the section's
/// convex hull (Bond::section): tension fibre s_t = max(N/A, max sigma), compression fibre
/// s_c = min(N/A, min sigma). This is M c / I exactly for any section shape, including sections whose
/// principal axes are not unique (squares, discs: I_1 = I_2). Bonds built by hand without a hull use
/// s_b = |M_1| c_1 / I_1 + |M_2| c_2 / I_2 with s_t = N/A + s_b, s_c = N/A - s_b (conservative).
/// Both extreme fibres are checked: the tension one against the tensile strength, the compression one
/// against the compressive strength.
/// Shear: tau = V / A + |T| r_max / J, the average shear (not the 1.5 V / A peak of a rectangle: bond
/// sections are arbitrary polygons, and the average is what the section carries everywhere) plus the
/// torsion of a circular section of radius r_max (exact for discs, conservative for compact sections).
/// Utilization = max(criterion(s_t, tau) / f_t if s_t > 0, criterion(s_c, tau) / f_c if s_c < 0,
/// tau / f_s), with criterion Tresca sqrt(s^2 + 4 tau^2) or von Mises sqrt(s^2 + 3 tau^2).

#include "algorithms/bonds/support_graph.h"
#include "algorithms/core/material.h"
#include "algorithms/stress/rigid_body_spring/spring_system.h"
#include "algorithms/stress/stress_model.h"

namespace shatter {

/// Which equivalent stress combines sigma and tau.
enum class Criterion {
  tresca,     ///< sqrt(sigma^2 + 4 tau^2)
  von_mises,  ///< sqrt(sigma^2 + 3 tau^2)
};

/// Equivalent stress of a normal stress `sigma` and a shear stress `tau` (Pa).
double equivalent_stress(Criterion criterion, double sigma, double tau);

/// Forces, stresses and utilization of `bond` carrying `forces` (see the header note).
BondStress bond_stress(const Bond& bond, const BondForces& forces, const Material& material, Criterion criterion);

}  // namespace shatter
