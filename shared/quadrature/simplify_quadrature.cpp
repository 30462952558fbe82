#include "shared/quadrature/simplify_quadrature.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "shared/common/eigen_decompositions.hpp"
#include "shared/quadrature/basic_feasible_point.hpp"
#include "shared/quadrature/caratheodory_recombination.hpp"
#include "shared/quadrature/chebyshev_moment_matrix.hpp"
#include "shared/quadrature/nonnegative_least_squares.hpp"

namespace altfem {
namespace {

/// Rows whose pivot falls below this fraction of the largest are taken as dependent.
constexpr double rank_threshold = 1e-12;
/// Smallest reciprocal condition number of P Pᵀ for the Cholesky route: its rows are
/// then orthonormal to about 1e-16 / 1e-7 = 1e-9, plenty for an equivalent system.
constexpr double minimum_gram_rcond = 1e-7;
/// The largest moment residual, relative to the weights' sum, at which the LU's re-solve
/// of the weights is kept (the QR's otherwise): a hundredth of the default tolerance.
constexpr double lu_residual = 1e-14;
/// Candidate weights below this fraction of the total are dropped before polishing.
constexpr double negligible_weight = 1e-14;

/// Rows spanning P's row space, orthonormal (r × N): Longva et al. 2020, §4.4.4, eq. (10):
/// P w = P w⁰ ⇔ Vᵣᵀ w = Vᵣᵀ w⁰ for any orthonormal basis Vᵣ of that space, and the
/// transformed system is perfectly conditioned. The fast route is a Cholesky factor of
/// the small Gram matrix P Pᵀ = L Lᵀ, whose L⁻¹ P has orthonormal rows; it squares P's
/// condition number, so when the factor fails or P Pᵀ is ill-conditioned (nearly
/// dependent moments), a pivoted QR of Pᵀ, which also reveals the rank, is used instead.
Eigen::MatrixXd orthonormal_row_basis(const Eigen::MatrixXd& moments) {
  const Eigen::Index rows = moments.rows();
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(rows, rows);
  gram.selfadjointView<Eigen::Lower>().rankUpdate(moments);
  const Eigen::LLT<Eigen::MatrixXd> cholesky(gram.selfadjointView<Eigen::Lower>());
  // The rows of L⁻¹ P are orthonormal up to about ε · cond(P Pᵀ).
  if (cholesky.info() == Eigen::Success && cholesky.rcond() >= minimum_gram_rcond) {
    return cholesky.matrixL().solve(moments);
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(moments.transpose());
  qr.setThreshold(rank_threshold);
  const Eigen::MatrixXd basis = qr.householderQ() * Eigen::MatrixXd::Identity(moments.cols(), qr.rank());
  return basis.transpose();
}

/// The candidate weights of the LP or NNLS on the orthonormal system A w = b; empty on failure.
Eigen::VectorXd solve_weights(SimplificationMethod method, const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  if (method == SimplificationMethod::linear_program) {
    auto solution = basic_feasible_point(A, b);
    return solution ? *solution : Eigen::VectorXd();
  }
  NonnegativeLeastSquaresResult result = nonnegative_least_squares(A, b);
  return result.converged ? result.solution : Eigen::VectorXd();
}

}  // namespace

std::optional<SimplificationMethod> simplifier_from_name(std::string_view name) {
  if (name == "none") return std::nullopt;
  for (const SimplificationMethod method :
       {SimplificationMethod::caratheodory, SimplificationMethod::nonnegative_least_squares,
        SimplificationMethod::linear_program})
    if (simplification_method_name(method) == name) return method;
  throw std::invalid_argument("unknown quadrature simplifier '" + std::string(name) + "'");
}

std::string_view simplification_method_name(SimplificationMethod method) {
  switch (method) {
    case SimplificationMethod::linear_program: return "lp";
    case SimplificationMethod::nonnegative_least_squares: return "nnls";
    case SimplificationMethod::caratheodory: return "caratheodory";
  }
  return "?";
}

SimplificationResult simplify_quadrature(const QuadratureRule& rule, const SimplificationOptions& options) {
  if (options.degree < 0) throw std::invalid_argument("simplify_quadrature: degree must be >= 0");
  if (rule.points.cols() != 3 || rule.points.rows() != rule.weights.size()) {
    throw std::invalid_argument("simplify_quadrature: points must be #points x 3, one weight each");
  }
  if ((rule.weights.array() < 0.0).any()) throw std::invalid_argument("simplify_quadrature: negative weight");
  SimplificationResult result;
  result.rule = rule;
  const Eigen::Index count = rule.points.rows();
  const Eigen::Index basis_size = (options.degree + 1) * (options.degree + 2) * (options.degree + 3) / 6;
  if (count <= basis_size) return result;

  const Eigen::MatrixXd moments = chebyshev_moment_matrix(rule.points, options.degree);  // M × N
  const Eigen::VectorXd target = moments * rule.weights;

  // The system the candidate's weights are re-solved on: the orthonormal one of eq. (10)
  // for the LP and NNLS; recombination needs no transform (its null spaces are those of
  // P) and re-solves on P itself by a pivoted QR, stable at any row scaling.
  Eigen::MatrixXd A;  // r × N
  Eigen::VectorXd b, candidate;
  if (options.method == SimplificationMethod::caratheodory) {
    candidate = caratheodory_recombination(moments, rule.weights, basis_size);
  } else {
    A = orthonormal_row_basis(moments);
    b = A * rule.weights;
    candidate = solve_weights(options.method, A, b);
  }
  const Eigen::MatrixXd& system = A.size() > 0 ? A : moments;
  const Eigen::VectorXd& rhs = A.size() > 0 ? b : target;
  // Weights at rounding level are zeros the solver did not land on exactly; keeping
  // them would give points that carry nothing.
  const double negligible = negligible_weight * rule.weights.sum();
  std::vector<Eigen::Index> support;
  for (Eigen::Index j = 0; j < candidate.size(); ++j) {
    if (candidate(j) > negligible) support.push_back(j);
  }
  const Eigen::Index kept = static_cast<Eigen::Index>(support.size());
  if (candidate.size() == 0 || kept == 0 || kept > basis_size) {
    result.failed = true;
    return result;
  }

  // Re-solve the weights on the chosen points: the solvers stop at their own
  // tolerances; the square (or overdetermined) system on the support is exact.
  Eigen::MatrixXd chosen(system.rows(), kept);
  Eigen::VectorXd weights(kept);
  for (Eigen::Index i = 0; i < kept; ++i) {
    chosen.col(i) = system.col(support[i]);
    weights(i) = candidate(support[i]);
  }
  // A square system (as many points as moments, recombination's usual outcome) by LU with
  // partial pivoting, a fraction of the pivoted QR's cost at 35 × 35 (the QR was 5% of fcm
  // Hex20's refine event, `perf`), kept when it reproduces the moments to round-off; else,
  // and for an overdetermined system, the QR.
  Eigen::VectorXd polished;
  if (kept == system.rows()) {
    polished = Eigen::PartialPivLU<Eigen::MatrixXd>(chosen).solve(rhs);
    const double residual = (chosen * polished - rhs).cwiseAbs().maxCoeff();
    if (!(residual <= lu_residual * rule.weights.sum())) polished.resize(0);
  }
  if (polished.size() == 0) polished = chosen.colPivHouseholderQr().solve(rhs);
  if ((polished.array() > 0.0).all()) weights = polished;

  QuadratureRule simplified;
  simplified.points.resize(kept, 3);
  for (Eigen::Index i = 0; i < kept; ++i) simplified.points.row(i) = rule.points.row(support[i]);
  simplified.weights = weights;
  simplified.strength = std::min(rule.strength, options.degree);

  Eigen::MatrixXd chosen_moments(moments.rows(), kept);
  for (Eigen::Index i = 0; i < kept; ++i) chosen_moments.col(i) = moments.col(support[i]);
  result.residual = (chosen_moments * weights - target).cwiseAbs().maxCoeff() / rule.weights.sum();
  if (!(result.residual <= options.tolerance)) {
    result.failed = true;
    return result;
  }
  result.rule = std::move(simplified);
  result.simplified = true;
  return result;
}

}  // namespace altfem
