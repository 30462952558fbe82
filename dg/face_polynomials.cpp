#include "dg/face_polynomials.hpp"

#include "shared/geometry/monomial_shift.hpp"
#include "shared/geometry/polygon_moments.hpp"

namespace altfem::dg {

namespace {
using Exponent = Eigen::Matrix<int, 1, 3>;
}  // namespace

// The change of frame is what shift_moments computes for moments:
// (offset + ratio ξ)^α = Σ_β S(α, β) ξ^β, read off column by column from unit "moments".
FunctionsInFrame in_frame(const MonomialBasis& basis, const Eigen::Vector3d& centre, double scale, int degree) {
  const int count = monomial_count(degree);
  const Eigen::Vector3d offset = (centre - basis.centre()) / basis.scale();
  const double ratio = scale / basis.scale();
  Eigen::MatrixXd S(count, count);  // S(α, β): row α = basis monomial, column β = frame monomial
  for (int beta = 0; beta < count; ++beta)
    S.col(beta) = shift_moments(Eigen::VectorXd::Unit(count, beta), degree, offset, ratio);
  FunctionsInFrame functions;
  const auto& exponents = basis.exponents();
  for (int a = 0; a < basis.size(); ++a) {
    functions.values.push_back(S.row(monomial_index(Exponent(exponents.row(a)))).transpose());
    std::array<Polynomial, 3> gradient;
    for (int d = 0; d < 3; ++d) {
      gradient[d] = Polynomial::Zero(count);
      if (exponents(a, d) == 0) continue;
      Exponent lowered = exponents.row(a);
      --lowered(d);
      gradient[d] = exponents(a, d) / basis.scale() * S.row(monomial_index(lowered)).transpose();
    }
    functions.gradients.push_back(gradient);
  }
  const Eigen::MatrixXd& combination = basis.combination();
  if (combination.size() == 0) return functions;
  FunctionsInFrame combined;  // φ_j = Σ_a C_aj m_a, and so their gradients
  for (int j = 0; j < basis.size(); ++j) {
    Polynomial value = Polynomial::Zero(count);
    std::array<Polynomial, 3> gradient{value, value, value};
    for (int a = 0; a < basis.size(); ++a) {
      value += combination(a, j) * functions.values[a];
      for (int d = 0; d < 3; ++d) gradient[d] += combination(a, j) * functions.gradients[a][d];
    }
    combined.values.push_back(std::move(value));
    combined.gradients.push_back(std::move(gradient));
  }
  return combined;
}


FaceIntegrals::FaceIntegrals(const Eigen::MatrixXd& polygon, int degree, const Eigen::Vector3d& centre, double scale)
    : moments_(planar_polygon_moments(polygon, 2 * degree, centre, scale)), exponents_(monomial_exponents(degree)) {}

double FaceIntegrals::product(const Polynomial& p, const Polynomial& q) const {
  double total = 0;
  for (Eigen::Index i = 0; i < p.size(); ++i) {
    if (p[i] == 0) continue;
    for (Eigen::Index j = 0; j < q.size(); ++j)
      if (q[j] != 0) total += p[i] * q[j] * moments_[monomial_index(Exponent(exponents_.row(i) + exponents_.row(j)))];
  }
  return total;
}

}  // namespace altfem::dg
