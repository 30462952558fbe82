#include "shared/quadrature/nonnegative_least_squares.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <limits>
#include <vector>

#include "shared/common/eigen_decompositions.hpp"

namespace altfem {
namespace {

/// The least-squares solution on the passive columns (all others zero).
Eigen::VectorXd passive_solution(const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::VectorXd>& b,
                                 const std::vector<Eigen::Index>& passive, Eigen::MatrixXd& workspace) {
  const Eigen::Index k = static_cast<Eigen::Index>(passive.size());
  workspace.resize(A.rows(), k);
  for (Eigen::Index i = 0; i < k; ++i) workspace.col(i) = A.col(passive[i]);
  const Eigen::VectorXd z = workspace.colPivHouseholderQr().solve(b);
  Eigen::VectorXd full = Eigen::VectorXd::Zero(A.cols());
  for (Eigen::Index i = 0; i < k; ++i) full(passive[i]) = z(i);
  return full;
}

}  // namespace

NonnegativeLeastSquaresResult nonnegative_least_squares(const Eigen::Ref<const Eigen::MatrixXd>& A,
                                                        const Eigen::Ref<const Eigen::VectorXd>& b,
                                                        double gradient_tolerance) {
  const Eigen::Index columns = A.cols();
  NonnegativeLeastSquaresResult result{Eigen::VectorXd::Zero(columns), b.norm(), 0, false};
  std::vector<char> is_passive(columns, 0);
  std::vector<Eigen::Index> passive;
  Eigen::MatrixXd workspace;
  const double threshold = gradient_tolerance * std::max(b.norm(), std::numeric_limits<double>::min());
  Eigen::VectorXd& x = result.solution;
  const int max_iterations = static_cast<int>(3 * columns);

  Eigen::VectorXd gradient(columns);
  while (result.iterations < max_iterations) {
    // x is zero outside the passive set: its product with A costs rows × |passive|.
    Eigen::VectorXd residual = b;
    for (const Eigen::Index j : passive) residual -= x(j) * A.col(j);
    gradient.noalias() = A.transpose() * residual;
    Eigen::Index best = -1;
    double best_value = threshold;
    for (Eigen::Index j = 0; j < columns; ++j) {
      if (!is_passive[j] && gradient(j) > best_value) {
        best_value = gradient(j);
        best = j;
      }
    }
    if (best < 0 || static_cast<Eigen::Index>(passive.size()) >= A.rows()) {
      result.converged = true;
      break;
    }
    ++result.iterations;
    is_passive[best] = 1;
    passive.push_back(best);

    // Inner loop: step towards the unconstrained passive solution, stopping at the
    // first passive variable that would turn non-positive, and release it.
    for (int inner = 0; inner <= static_cast<int>(A.rows()); ++inner) {
      const Eigen::VectorXd z = passive_solution(A, b, passive, workspace);
      double step = 1.0;
      bool feasible = true;
      for (const Eigen::Index j : passive) {
        if (z(j) <= 0.0) {
          feasible = false;
          step = std::min(step, x(j) / (x(j) - z(j)));
        }
      }
      if (feasible) {
        x = z;
        break;
      }
      x += step * (z - x);
      std::vector<Eigen::Index> kept;
      for (const Eigen::Index j : passive) {
        if (x(j) > 0.0) {
          kept.push_back(j);
        } else {
          x(j) = 0.0;
          is_passive[j] = 0;
        }
      }
      passive = std::move(kept);
    }
  }
  result.residual_norm = (A * x - b).norm();
  return result;
}

}  // namespace altfem
