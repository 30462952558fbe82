#include "dg/monomial_basis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "shared/geometry/polyhedron_moments.hpp"

namespace altfem::dg {

MonomialBasis::MonomialBasis(int degree, const Eigen::Vector3d& centre, double scale)
    : degree_(degree), centre_(centre), scale_(scale), exponents_(monomial_exponents(degree)) {
  if (!(scale > 0) || !std::isfinite(scale)) throw std::invalid_argument("MonomialBasis: the scale must be positive");
}

void MonomialBasis::evaluate(const Eigen::Vector3d& x, Eigen::VectorXd& values, Eigen::MatrixXd& gradients) const {
  const Eigen::Vector3d local = (x - centre_) / scale_;
  // Powers ξ_d^p for p ≤ degree, per axis.
  Eigen::MatrixXd powers(degree_ + 1, 3);
  powers.row(0).setOnes();
  for (int p = 1; p <= degree_; ++p) powers.row(p) = powers.row(p - 1).cwiseProduct(local.transpose());
  values.resize(size());
  gradients.resize(size(), 3);
  for (int a = 0; a < size(); ++a) {
    const auto alpha = exponents_.row(a);
    values[a] = powers(alpha(0), 0) * powers(alpha(1), 1) * powers(alpha(2), 2);
    for (int d = 0; d < 3; ++d) {
      if (alpha(d) == 0) {
        gradients(a, d) = 0;
        continue;
      }
      double derivative = alpha(d) / scale_;
      for (int e = 0; e < 3; ++e) derivative *= powers(e == d ? alpha(e) - 1 : alpha(e), e);
      gradients(a, d) = derivative;
    }
  }
  if (combination_.size() == 0) return;
  values = combination_.transpose() * values;
  gradients = combination_.transpose() * gradients;
}

void MonomialBasis::combine(Eigen::MatrixXd combination) {
  if (combination.rows() != size() || combination.cols() != size())
    throw std::invalid_argument("MonomialBasis::combine: the combination must be " + std::to_string(size()) +
                                " square, got " + std::to_string(combination.rows()) + " x " +
                                std::to_string(combination.cols()));
  combination_ = std::move(combination);
}

MonomialBasis cell_monomial_basis(const Polyhedron& cell, int degree) {
  const Eigen::VectorXd first = polyhedron_moments(cell, 1);
  const Eigen::Vector3d centroid = first.segment<3>(1) / first[0];
  double diameter = 0;
  for (Eigen::Index i = 0; i < cell.vertices.rows(); ++i)
    for (Eigen::Index j = i + 1; j < cell.vertices.rows(); ++j)
      diameter = std::max(diameter, (cell.vertices.row(i) - cell.vertices.row(j)).norm());
  return MonomialBasis(degree, centroid, diameter);
}

}  // namespace altfem::dg
