#pragma once
// Block relaxation over blocks of consecutive DOFs (DG's element blocks, a vertex's three
// displacement components), each block solved exactly. With D the block diagonal of A and L
// its strictly lower block part in the sweeps' order:
//   jacobi                M = D                      every block on its own, in parallel.
//   gauss_seidel          M = D + L                  one sweep; apply_transpose() runs it
//                         backwards (M = D + Lᵀ). Not symmetric: the pre- and post-smoother
//                         of a symmetric V-cycle.
//   symmetric_gauss_seidel  M = (D + L) D⁻¹ (D + Lᵀ)  a forward and a backward sweep;
//                         symmetric positive definite when A is, so PCG may use it alone.
// On one thread, or with too few blocks to share, the sweeps go in the blocks' order
// (lexicographic); else in a multicolour order: the blocks are coloured greedily so that no
// two blocks of a colour are coupled by A, a sweep visits the colours in turn and the blocks of
// one colour in parallel (Saad 2003, §12.4).
// Where block Jacobi (D alone) ignores the coupling of neighbouring blocks, a sweep passes it
// on: as the smoother of a vertex-space level it damps the errors that vary from vertex to
// vertex without the damping factor Jacobi needs.
#include <vector>

#include "shared/solve/preconditioner.hpp"

namespace altfem {

enum class BlockRelaxation { jacobi, gauss_seidel, symmetric_gauss_seidel };

class BlockRelaxationPreconditioner final : public Preconditioner {
public:
  /// block_starts: #blocks + 1 increasing DOF indices from 0 to #dofs; block b is the DOFs
  /// [block_starts[b], block_starts[b + 1]).
  BlockRelaxationPreconditioner(std::vector<int> block_starts, BlockRelaxation relaxation);

  /// Inverts every diagonal block and, for Gauss–Seidel on several threads, colours the blocks
  /// by A's pattern. `matrix` must stay alive and unchanged until the next compute(). Throws
  /// NumericalError naming the first block that is not positive definite.
  void compute(const Eigen::SparseMatrix<double>& matrix) override;
  void apply(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const override;
  void apply_transpose(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const override;
  bool symmetric() const override { return relaxation_ != BlockRelaxation::gauss_seidel; }
  /// The Gauss–Seidel sweeps when they run on one thread (lexicographic: colour_count() 0):
  /// each relaxation updates the defect of its neighbours from its own columns, so the defect
  /// comes at no extra pass over A. False for Jacobi and for multicolour sweeps.
  bool apply_with_defect(const Eigen::VectorXd& residual, Eigen::VectorXd& result,
                         Eigen::VectorXd& defect) const override;

  /// The colours of the multicolour sweeps; 0 when they run on one thread in lexicographic
  /// order (one OpenMP thread, or fewer blocks than are worth sharing).
  int colour_count() const { return static_cast<int>(colour_starts_.size()) - 1; }

private:
  // One sweep over all blocks, forward or backward: lexicographic on one thread (serial_),
  // else colour after colour. after_forward: skip what a forward sweep relaxed last.
  void sweep_forward(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const;
  void sweep_backward(bool after_forward, const Eigen::VectorXd& residual, Eigen::VectorXd& result) const;
  int block_count() const { return static_cast<int>(block_starts_.size()) - 1; }
  // δ = D_b⁻¹ d_b, x_b += δ, d −= A e_b δ: block b relaxed against the defect d = r − A x,
  // which stays current (one thread only: two blocks of a colour may share a neighbour).
  void relax_updating(int block, Eigen::VectorXd& defect, Eigen::VectorXd& result) const;
  // x_b ← x_b + D_b⁻¹ (r_b − (A x)_b): block b relaxed against the current x.
  void relax(int block, const Eigen::VectorXd& residual, Eigen::VectorXd& result) const;

  std::vector<int> block_starts_;
  BlockRelaxation relaxation_;
  const Eigen::SparseMatrix<double>* matrix_ = nullptr;
  std::vector<double> inverses_;       // D_b⁻¹, column-major, one after another
  std::vector<long> inverse_offsets_;  // #blocks + 1
  bool serial_ = true;                 // lexicographic sweeps on one thread (see apply_with_defect)
  std::vector<char> same_rows_;        // per block: its columns have identical row indices
  std::vector<int> blocks_by_colour_;  // the blocks, colour after colour
  std::vector<int> colour_starts_;     // #colours + 1 offsets into blocks_by_colour_
};

}  // namespace altfem
