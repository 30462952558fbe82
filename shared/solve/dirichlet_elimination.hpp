#pragma once
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace altfem {

/// Strong Dirichlet conditions by elimination that keeps one sparsity pattern for the
/// whole run: the rows and columns of constrained DOFs are zeroed except their
/// diagonal, after moving the known columns to the right-hand side. Solving
///   K' Δu = r'  with  r'_f = r_f − K_fc Δc,  r'_c = K_cc Δc
/// gives Δu_c = Δc exactly and the free part of the eliminated system K_ff Δu_f =
/// r_f − K_fc Δc. The positions to zero are found once from the pattern.
class DirichletElimination {
public:
  DirichletElimination(const Eigen::SparseMatrix<double>& pattern, std::vector<int> constrained_dofs);

  const std::vector<int>& constrained_dofs() const { return constrained_; }
  bool is_constrained(int dof) const { return mask_[dof] != 0; }

  /// Applies the elimination to `matrix` (with the pattern) and `rhs`, for the
  /// prescribed increments `increment` of the constrained DOFs (constrained_dofs() order).
  void apply(Eigen::SparseMatrix<double>& matrix, Eigen::VectorXd& rhs, const Eigen::VectorXd& increment) const {
    lift(matrix, rhs, increment);
    eliminate(matrix);
  }
  /// The right-hand side part of apply(), from the matrix before elimination.
  void lift(const Eigen::SparseMatrix<double>& matrix, Eigen::VectorXd& rhs, const Eigen::VectorXd& increment) const;
  /// The matrix part of apply().
  void eliminate(Eigen::SparseMatrix<double>& matrix) const;
  /// Euclidean norm of the free entries of a #dofs vector.
  double free_norm(const Eigen::VectorXd& vector) const;
  /// Writes `values` (constrained_dofs() order) into the constrained entries.
  void set_constrained(Eigen::VectorXd& vector, const Eigen::VectorXd& values) const;
  /// The constrained entries of a #dofs vector (constrained_dofs() order).
  Eigen::VectorXd constrained_values(const Eigen::VectorXd& vector) const;

private:
  std::vector<int> constrained_;
  std::vector<char> mask_;
  std::vector<long long> off_diagonal_positions_;  // value indices to zero
  std::vector<long long> diagonal_positions_;      // per constrained DOF
};

}  // namespace altfem
