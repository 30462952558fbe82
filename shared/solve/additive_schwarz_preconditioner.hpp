#pragma once
// The Additive-Schwarz preconditioner of the finite cell method (Longva et al. 2020
// §5.2, after de Prenter et al. 2017, 2019), and with disjoint element blocks DG's
// block Jacobi (Kaufmann et al. 2009):
//   S = Σ_K R_Kᵀ C_K⁺ R_K + D⁻¹ on the DOFs of no block   (eq. (13)),
// where C_K = R_K C R_Kᵀ is the submatrix of the system matrix on block K's DOFs (it
// includes the neighbours' contributions) and C_K⁺ its *reflected* pseudo-inverse
// (eq. (14)): with C_K = Σ λ_k q_k q_kᵀ,
//   C_K⁺ = Σ μ_k q_k q_kᵀ,  μ_k = 1/|λ_k| if |λ_k| ≥ ε λ_max, else ε/|λ_max|.
// Reflecting the eigenvalues (not truncating them) keeps S positive definite even when
// C is indefinite (non-linear materials), as MINRES requires.
#include <vector>

#include "shared/solve/preconditioner.hpp"

namespace altfem {

class AdditiveSchwarzPreconditioner final : public Preconditioner {
public:
  /// blocks: lists of DOFs (each sorted or not; blocks may overlap, and then their
  /// contributions add as in eq. (13)). epsilon: ε of eq. (14).
  explicit AdditiveSchwarzPreconditioner(std::vector<std::vector<int>> blocks, double epsilon = 1e-13);

  /// Extracts and decomposes every C_K (in parallel over blocks); DOFs in no block get
  /// 1/|C_ii|. Throws NumericalError naming the row of a zero diagonal outside blocks,
  /// or a block whose eigen-solver fails or whose largest eigenvalue is zero.
  void compute(const Eigen::SparseMatrix<double>& matrix) override;
  /// compute() of the sum of the ranks' shares: each rank's C_K and diagonal summed across
  /// the ranks (Σ_K |K|² + #dofs values), then decomposed on every rank.
  bool computes_from_shares() const override { return true; }
  /// The most blocks that hold one DOF (1 where none overlap): for e_i, a DOF in n blocks,
  /// (A e_i)ᵀ S (A e_i) ≥ n · e_iᵀ A e_i, since each block K holding i gives
  /// (C_K e_i)ᵀ C_K⁻¹ (C_K e_i) = A_ii.
  double largest_eigenvalue_at_least() const override { return largest_overlap_; }
  void compute_from_shares(const Eigen::SparseMatrix<double>& share) override;
  void apply(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const override;

  int block_count() const { return static_cast<int>(blocks_.size()); }
  /// How many eigenvalues, over all blocks, were below ε λ_max and replaced.
  int reflected_small_eigenvalues() const { return small_eigenvalues_; }

private:
  // C_K of every block and the diagonal, as `matrix` holds them.
  void gather(const Eigen::SparseMatrix<double>& matrix, std::vector<Eigen::MatrixXd>& blocks,
              Eigen::VectorXd& diagonal) const;
  // C_K⁺ of every block and 1/|C_ii| of the DOFs in none.
  void decompose(std::vector<Eigen::MatrixXd>& blocks, const Eigen::VectorXd& diagonal);

  std::vector<std::vector<int>> blocks_;  // each sorted
  double epsilon_;
  std::vector<Eigen::MatrixXd> inverses_;                     // C_K⁺ per block
  Eigen::VectorXd diagonal_inverse_;                          // 1/|C_ii| for DOFs in no block, else 0
  mutable std::vector<Eigen::VectorXd> gathered_, products_;  // per block scratch: apply() must not allocate
  int small_eigenvalues_ = 0;
  int largest_overlap_ = 1;
};

}  // namespace altfem
