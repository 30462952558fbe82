#include "shared/material/lame_parameters.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "shared/common/error.hpp"

namespace altfem {
namespace {

std::string shortest(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace

LameParameters lame_parameters(double youngs_modulus, double poisson_ratio) {
  if (!(std::isfinite(youngs_modulus) && youngs_modulus > 0.0)) {
    throw InputError("material: youngs_modulus: expected a finite number > 0, got " + shortest(youngs_modulus));
  }
  // ν → 1/2 makes λ infinite (incompressible) and ν → −1 makes μ infinite.
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5)) {
    throw InputError("material: poisson_ratio: expected a number in (-1, 0.5), got " + shortest(poisson_ratio));
  }
  const double E = youngs_modulus;
  const double nu = poisson_ratio;
  return {E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

}  // namespace altfem
