#include "shared/assembly/element_masses.hpp"

namespace altfem {

void ElementMasses::append(const TabulatedElements& elements) {
  const int first = size();
  const int count = elements.size();
  matrices.resize(first + count);
  integrals.resize(first + count);
  volumes.resize(first + count);
#pragma omp parallel for schedule(dynamic, 16)
  for (int e = 0; e < count; ++e) {
    Eigen::MatrixXd& matrix = matrices[first + e];
    Eigen::VectorXd& integral = integrals[first + e];
    if (!elements.holds(e)) {  // another rank's: no entry
      matrix.resize(0, 0);
      integral.resize(0);
      volumes[first + e] = 0;
      continue;
    }
    const ElementView element = elements[e];
    const int n = element.basis_count();
    matrix.setZero(n, n);
    integral.setZero(n);
    double volume = 0;
    for (int q = 0; q < element.point_count(); ++q) {
      const double weight = element.weights[q];
      volume += weight;
      for (int b = 0; b < n; ++b) {
        const double weighted = weight * element.values(q, b);
        integral[b] += weighted;
        for (int a = 0; a < n; ++a) matrix(a, b) += weighted * element.values(q, a);
      }
    }
    volumes[first + e] = volume;
  }
}

ElementMasses element_masses(const TabulatedElements& elements) {
  ElementMasses masses;
  masses.append(elements);
  return masses;
}

}  // namespace altfem
