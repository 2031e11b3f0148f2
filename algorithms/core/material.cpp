#include "algorithms/core/material.h"

#include <cmath>
#include <string>
#include <utility>

namespace shatter {

namespace {

Status positive(double value, const char* key) {
  if (std::isfinite(value) && value > 0.0) return {};
  return Error{std::string("material: ") + key + " must be finite and > 0 (got " + std::to_string(value) + ")"};
}

}  // namespace

Status check_material(const Material& m) {
  for (const auto& [value, key] : {std::pair{m.density, "density"}, std::pair{m.young_modulus, "young_modulus"},
                                   std::pair{m.tensile_strength, "tensile_strength"},
                                   std::pair{m.compressive_strength, "compressive_strength"},
                                   std::pair{m.shear_strength, "shear_strength"}})
    if (Status s = positive(value, key); !s) return s;
  if (!(std::isfinite(m.poisson_ratio) && m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5))
    return Error{"material: poisson_ratio must be in (-1, 0.5) (got " + std::to_string(m.poisson_ratio) + ")"};
  return {};
}

}  // namespace shatter
