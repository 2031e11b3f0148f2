#pragma once
/// A brittle, linear-elastic material, SI units throughout. Read from the case file's "material"; used by
/// the stress models and by fracturers that solve for stress (fem-lite).
#include "algorithms/core/result.h"

namespace shatter {

/// Material constants; the defaults are a plain concrete.
struct Material {
  double density = 2400.0;               ///< kg/m^3, > 0
  double young_modulus = 3e10;           ///< Pa, > 0
  double poisson_ratio = 0.2;            ///< dimensionless, in (-1, 0.5)
  double tensile_strength = 3e6;         ///< Pa, > 0: limit of the peak tensile normal stress
  double compressive_strength = 3e7;     ///< Pa, > 0: limit of the peak compressive normal stress
  double shear_strength = 6e6;           ///< Pa, > 0: limit of the peak shear stress

  /// Shear modulus G = E / (2 (1 + nu)), Pa.
  [[nodiscard]] double shear_modulus() const { return young_modulus / (2.0 * (1.0 + poisson_ratio)); }
};

/// Error unless every material constant is finite and in range (names the field).
Status check_material(const Material& material);

}  // namespace shatter
