#include "shared/solve/dirichlet_elimination.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace altfem {

DirichletElimination::DirichletElimination(const Eigen::SparseMatrix<double>& pattern, std::vector<int> constrained)
    : constrained_(std::move(constrained)), mask_(pattern.rows(), 0) {
  std::sort(constrained_.begin(), constrained_.end());
  for (int dof : constrained_) {
    if (dof < 0 || dof >= pattern.rows())
      throw std::invalid_argument("DirichletElimination: DOF " + std::to_string(dof) + " out of range");
    mask_[dof] = 1;
  }
  diagonal_positions_.assign(constrained_.size(), -1);
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  for (Eigen::Index column = 0; column < pattern.cols(); ++column)
    for (int position = outer[column]; position < outer[column + 1]; ++position) {
      const int row = inner[position];
      if (row == column) {
        if (mask_[row]) {
          const auto where = std::lower_bound(constrained_.begin(), constrained_.end(), row) - constrained_.begin();
          diagonal_positions_[where] = position;
        }
      } else if (mask_[row] || mask_[column]) {
        off_diagonal_positions_.push_back(position);
      }
    }
  for (size_t i = 0; i < constrained_.size(); ++i)
    if (diagonal_positions_[i] < 0)
      throw std::invalid_argument("DirichletElimination: the pattern has no diagonal entry for DOF " +
                                  std::to_string(constrained_[i]));
}

namespace {
// An indefinite tangent may leave a non-positive diagonal; any positive value gives
// the same Δu_c, and 1 keeps the matrix positive definite.
double eliminated_diagonal(double diagonal) { return diagonal > 0 ? diagonal : 1.0; }
}  // namespace

void DirichletElimination::lift(const Eigen::SparseMatrix<double>& matrix, Eigen::VectorXd& rhs,
                                const Eigen::VectorXd& increment) const {
  if (increment.size() != static_cast<Eigen::Index>(constrained_.size()))
    throw std::invalid_argument("DirichletElimination: one increment per constrained DOF expected");
  if (increment.squaredNorm() > 0) {
    Eigen::VectorXd lifted = Eigen::VectorXd::Zero(matrix.rows());
    set_constrained(lifted, increment);
    rhs.noalias() -= matrix * lifted;
  }
  const double* values = matrix.valuePtr();
  for (size_t i = 0; i < constrained_.size(); ++i)
    rhs[constrained_[i]] =
        eliminated_diagonal(values[diagonal_positions_[i]]) * increment[static_cast<Eigen::Index>(i)];
}

void DirichletElimination::eliminate(Eigen::SparseMatrix<double>& matrix) const {
  double* values = matrix.valuePtr();
  for (long long position : off_diagonal_positions_) values[position] = 0.0;
  for (long long position : diagonal_positions_) values[position] = eliminated_diagonal(values[position]);
}

double DirichletElimination::free_norm(const Eigen::VectorXd& vector) const {
  double sum = 0;
  for (Eigen::Index dof = 0; dof < vector.size(); ++dof)
    if (!mask_[dof]) sum += vector[dof] * vector[dof];
  return std::sqrt(sum);
}

void DirichletElimination::set_constrained(Eigen::VectorXd& vector, const Eigen::VectorXd& values) const {
  for (size_t i = 0; i < constrained_.size(); ++i) vector[constrained_[i]] = values[static_cast<Eigen::Index>(i)];
}

Eigen::VectorXd DirichletElimination::constrained_values(const Eigen::VectorXd& vector) const {
  Eigen::VectorXd values(static_cast<Eigen::Index>(constrained_.size()));
  for (size_t i = 0; i < constrained_.size(); ++i) values[static_cast<Eigen::Index>(i)] = vector[constrained_[i]];
  return values;
}

}  // namespace altfem
