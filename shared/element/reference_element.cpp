#include "shared/element/reference_element.hpp"

#include <Eigen/LU>
#include <array>
#include <stdexcept>
#include <string>

#include "shared/element/polynomial_space.hpp"
#include "shared/element/reference_nodes.hpp"

namespace altfem {

namespace {
// Stack storage for the monomials and their derivatives (no heap allocation on
// the evaluation path, which runs at every quadrature point).
using MonomialValues = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, ReferenceElement::max_node_count, 1>;
using MonomialGradients = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, ReferenceElement::max_node_count, 3>;
using MonomialHessians = Eigen::Matrix<double, Eigen::Dynamic, 9, 0, ReferenceElement::max_node_count, 9>;

constexpr int max_exponent = 3;  // Tet20's cubics
using Powers = std::array<std::array<double, max_exponent + 1>, 3>;

/// powers[d][k] = ξ_d^k.
Powers powers_of(const Eigen::Vector3d& xi) {
  Powers powers{};
  for (int d = 0; d < 3; ++d) {
    powers[d][0] = 1.0;
    for (int k = 1; k <= max_exponent; ++k) powers[d][k] = powers[d][k - 1] * xi[d];
  }
  return powers;
}

double monomial(const Powers& powers, const Eigen::Vector3i& exponent) {
  return powers[0][exponent[0]] * powers[1][exponent[1]] * powers[2][exponent[2]];
}
}  // namespace

ReferenceElement::ReferenceElement(ElementType type)
    : type_(type), nodes_(reference_nodes(type)), exponents_(polynomial_space_exponents(type)) {
  const int count = node_count();
  if (static_cast<int>(exponents_.size()) != count)
    throw std::logic_error("ReferenceElement: " + std::string(element_name(type)) + " has " + std::to_string(count) +
                           " nodes but " + std::to_string(exponents_.size()) + " monomials");
  Eigen::MatrixXd vandermonde(count, count);
  for (int i = 0; i < count; ++i) {
    const Powers powers = powers_of(nodes_.row(i).transpose());
    for (int j = 0; j < count; ++j) vandermonde(i, j) = monomial(powers, exponents_[j]);
  }
  // Li's eq. (4.23): Vᵀ N = m(ξ), hence N = V^{-T} m(ξ).
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(vandermonde.transpose());
  if (!lu.isInvertible())
    throw std::logic_error("ReferenceElement: the nodes of " + std::string(element_name(type)) +
                           " are not unisolvent for its polynomial space");
  coefficients_ = lu.inverse();
}

Eigen::Vector3d ReferenceElement::centroid() const {
  return shape() == ElementShape::tetrahedron ? Eigen::Vector3d::Constant(0.25) : Eigen::Vector3d::Zero();
}

void ReferenceElement::evaluate(const Eigen::Vector3d& xi, Eigen::Ref<Eigen::VectorXd> values) const {
  const int count = node_count();
  const Powers powers = powers_of(xi);
  MonomialValues monomials(count);
  for (int j = 0; j < count; ++j) monomials[j] = monomial(powers, exponents_[j]);
  values.noalias() = coefficients_.lazyProduct(monomials);
}

void ReferenceElement::evaluate_gradients(const Eigen::Vector3d& xi, Eigen::Ref<Eigen::MatrixXd> gradients) const {
  const int count = node_count();
  const Powers powers = powers_of(xi);
  MonomialGradients derivatives(count, 3);
  for (int j = 0; j < count; ++j) {
    const Eigen::Vector3i& exponent = exponents_[j];
    for (int d = 0; d < 3; ++d) {
      if (exponent[d] == 0) {
        derivatives(j, d) = 0.0;
        continue;
      }
      Eigen::Vector3i lowered = exponent;
      --lowered[d];
      derivatives(j, d) = exponent[d] * monomial(powers, lowered);
    }
  }
  gradients.noalias() = coefficients_.lazyProduct(derivatives);
}

void ReferenceElement::evaluate_hessians(const Eigen::Vector3d& xi, Eigen::Ref<Eigen::MatrixXd> hessians) const {
  const int count = node_count();
  const Powers powers = powers_of(xi);
  MonomialHessians derivatives(count, 9);
  for (int j = 0; j < count; ++j)
    for (int d = 0; d < 3; ++d)
      for (int e = 0; e < 3; ++e) {
        // ∂_d ∂_e ξ^a: lower exponent d, then e, each time by the factor it had.
        Eigen::Vector3i lowered = exponents_[j];
        double factor = lowered[d];
        --lowered[d];
        factor *= lowered[e];
        --lowered[e];
        derivatives(j, 3 * d + e) = factor == 0.0 ? 0.0 : factor * monomial(powers, lowered);
      }
  hessians.noalias() = coefficients_.lazyProduct(derivatives);
}

namespace {
// Row q of the result holds the monomials (lowered by `derivative` when it is 0–2, with
// the factor the lowering brings) at point q; then one product with the coefficients gives
// every basis function at every point. Built a monomial (column) at a time from columns of
// powers, so that each step is one product over all points, which vectorises (the same
// products, in the same order, as `monomial` at one point: the same monomials, bit for
// bit). A point at a time, the exponents' look-ups became gathers, as costly as the
// product with the coefficients (`perf` of fcm Hex20's cut-cell masses).
void monomials_at(const Eigen::Ref<const Eigen::MatrixXd>& points, const std::vector<Eigen::Vector3i>& exponents,
                  int derivative, Eigen::MatrixXd& monomials) {
  const auto count = static_cast<int>(exponents.size());
  const Eigen::Index rows = points.rows();
  // powers[d] column k = ξ_d^k at every point (powers_of's recurrence).
  thread_local std::array<Eigen::MatrixXd, 3> powers;
  for (int d = 0; d < 3; ++d) {
    powers[d].resize(rows, max_exponent + 1);
    powers[d].col(0).setOnes();
    for (int k = 1; k <= max_exponent; ++k) powers[d].col(k) = powers[d].col(k - 1).cwiseProduct(points.col(d));
  }
  monomials.resize(rows, count);
  for (int j = 0; j < count; ++j) {
    Eigen::Vector3i exponent = exponents[j];
    if (derivative >= 0 && exponent[derivative] == 0) {
      monomials.col(j).setZero();
      continue;
    }
    if (derivative >= 0) --exponent[derivative];
    const auto product =
        powers[0].col(exponent[0]).cwiseProduct(powers[1].col(exponent[1])).cwiseProduct(powers[2].col(exponent[2]));
    if (derivative < 0) monomials.col(j) = product;
    else monomials.col(j) = static_cast<double>(exponents[j][derivative]) * product;
  }
}

// The monomials of a whole rule, reused by the calls on one thread: a cut cell's rule
// fills hundreds of kilobytes, which a fresh allocation per call takes from the kernel
// (mmap) and faults in page by page.
Eigen::MatrixXd& monomial_scratch() {
  thread_local Eigen::MatrixXd monomials;
  return monomials;
}
}  // namespace

void ReferenceElement::evaluate_at(const Eigen::Ref<const Eigen::MatrixXd>& points, Eigen::MatrixXd& values) const {
  Eigen::MatrixXd& monomials = monomial_scratch();
  monomials_at(points, exponents_, -1, monomials);
  values.noalias() = monomials * coefficients_.transpose();
}

void ReferenceElement::evaluate_gradients_at(const Eigen::Ref<const Eigen::MatrixXd>& points,
                                             std::array<Eigen::MatrixXd, 3>& gradients) const {
  Eigen::MatrixXd& monomials = monomial_scratch();
  for (int j = 0; j < 3; ++j) {
    monomials_at(points, exponents_, j, monomials);
    gradients[j].noalias() = monomials * coefficients_.transpose();
  }
}

void ReferenceElement::integrate_products(const Eigen::Ref<const Eigen::MatrixXd>& points,
                                          const Eigen::Ref<const Eigen::VectorXd>& weights, Eigen::MatrixXd& products,
                                          Eigen::VectorXd& integrals) const {
  thread_local Eigen::MatrixXd values, weighted;  // #points × #nodes
  evaluate_at(points, values);
  weighted = values.array().colwise() * weights.array();
  const Eigen::Index count = values.cols();
  products.setZero(count, count);
  products.triangularView<Eigen::Lower>() = values.transpose() * weighted;
  products = products.selfadjointView<Eigen::Lower>();
  integrals.noalias() = values.transpose() * weights;
}

bool ReferenceElement::contains(const Eigen::Vector3d& xi, double tolerance) const {
  if (shape() == ElementShape::tetrahedron) return xi.minCoeff() >= -tolerance && xi.sum() <= 1.0 + tolerance;
  return xi.cwiseAbs().maxCoeff() <= 1.0 + tolerance;
}

const ReferenceElement& reference_element(ElementType type) {
  // A function-local static is initialised once, thread-safely (C++11 [stmt.dcl]/4).
  static const std::array<ReferenceElement, 6> elements{
      ReferenceElement(ElementType::tet4), ReferenceElement(ElementType::tet10), ReferenceElement(ElementType::tet20),
      ReferenceElement(ElementType::hex8), ReferenceElement(ElementType::hex20), ReferenceElement(ElementType::hex27)};
  return elements[static_cast<int>(type)];
}

}  // namespace altfem
