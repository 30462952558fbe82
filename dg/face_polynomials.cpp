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
  if (offset.isZero(0) && ratio == 1) {
    S.setIdentity();  // the basis's own frame (a face's minus side)
  } else {
    for (int beta = 0; beta < count; ++beta)
      S.col(beta) = shift_moments(Eigen::VectorXd::Unit(count, beta), degree, offset, ratio);
  }
  const auto& exponents = basis.exponents();
  FunctionsInFrame functions{Eigen::MatrixXd(count, basis.size()), {}};
  for (int d = 0; d < 3; ++d) functions.gradients[d] = Eigen::MatrixXd::Zero(count, basis.size());
  for (int a = 0; a < basis.size(); ++a) {
    functions.values.col(a) = S.row(monomial_index(Exponent(exponents.row(a)))).transpose();
    for (int d = 0; d < 3; ++d) {
      if (exponents(a, d) == 0) continue;
      Exponent lowered = exponents.row(a);
      --lowered(d);
      functions.gradients[d].col(a) = exponents(a, d) / basis.scale() * S.row(monomial_index(lowered)).transpose();
    }
  }
  // Combined functions φ_j = Σ_a C_aj m_a (dg/strong_conditions.hpp), and so their gradients.
  const Eigen::MatrixXd& combination = basis.combination();
  if (combination.size() == 0) return functions;
  functions.values *= combination;
  for (Eigen::MatrixXd& gradient : functions.gradients) gradient *= combination;
  return functions;
}

FaceIntegrals::FaceIntegrals(const Eigen::MatrixXd& polygon, int degree, const Eigen::Vector3d& centre, double scale) {
  const Eigen::VectorXd moments = planar_polygon_moments(polygon, 2 * degree, centre, scale);
  const Eigen::Matrix<int, Eigen::Dynamic, 3> exponents = monomial_exponents(degree);
  monomial_products_.resize(exponents.rows(), exponents.rows());
  for (Eigen::Index i = 0; i < exponents.rows(); ++i)
    for (Eigen::Index j = 0; j < exponents.rows(); ++j)
      monomial_products_(i, j) = moments[monomial_index(Exponent(exponents.row(i) + exponents.row(j)))];
}

}  // namespace altfem::dg
