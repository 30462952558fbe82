#include "shared/simulation/method_instance.hpp"

namespace altfem {

std::optional<double> MethodInstance::volume() const {
  const std::optional<FieldQuadrature> quadrature = field_quadrature(0);
  if (!quadrature) return std::nullopt;
  double volume = 0;
  for (int e = 0; e < quadrature->elements->size(); ++e)
    for (double weight : (*quadrature->elements)[e].weights) volume += weight;
  return quadrature->elements->sum_over_ranks(volume);
}

}  // namespace altfem
