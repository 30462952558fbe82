#pragma once
// A method's own preconditioner as the smoother of the finest level of PETSc's algebraic
// multigrid. fcm's cut cells leave functions whose support holds a
// sliver of material: their energy is tiny and local, so neither GAMG's point smoother
// (Chebyshev on the diagonal) nor its coarse spaces (smooth aggregates) reduce it, and CG
// takes about 1,100 iterations on the half-ball's 8 × 8 × 4 Hex20 grid (89 with this). The
// Additive Schwarz blocks of the small cut cells (Longva et al. 2020 §5.2) invert exactly
// that energy; as the fine smoother they leave GAMG the smooth error it reduces well.
// Over several ranks a preconditioner that can be set up from the ranks' shares of the
// matrix (Preconditioner::compute_from_shares: the Additive Schwarz blocks) is set up
// alike on every rank and applied to the whole residual, gathered from the ranks, each
// rank keeping its own rows of the result; any other leaves GAMG its own smoother.
#ifdef ALTFEM_HAVE_PETSC
#include <petscksp.h>

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "shared/solve/preconditioner.hpp"

namespace altfem {

class FinestLevelSmoother {
public:
  /// `factory`: the method's preconditioner (empty: none, and nothing is done);
  /// `over_ranks`: the solve runs over several ranks (then only a preconditioner that
  /// computes_from_shares is used).
  explicit FinestLevelSmoother(PreconditionerFactory factory, bool over_ranks = false);
  /// Whether there is a preconditioner to install.
  explicit operator bool() const { return static_cast<bool>(factory_); }

  /// Before the first set-up of `pc` (its type read from the options): with GAMG, every
  /// level's Chebyshev iteration estimates its own eigenvalue bounds, since the finest one
  /// must bound the spectrum the method's preconditioner leaves, not the Jacobi-smoothed
  /// one GAMG's aggregation estimates (97 iterations on the half-ball with those, 89 with
  /// its own) — unless `petsc_options` choose (-pc_gamg_use_sa_esteig). install() then
  /// bounds the finest level's Chebyshev iteration itself, unless the options choose its
  /// bounds (-…ksp_chebyshev_esteig or -…ksp_chebyshev_eigenvalues).
  PetscErrorCode configure(PC pc, const std::string& petsc_options);

  /// After every set-up of `pc` (a PCMG or PCGAMG; any other is left alone) on `matrix`
  /// (the method's numbering; over several ranks this rank's share when `matrix_is_share`,
  /// else the whole): the method's preconditioner computed on it becomes the
  /// preconditioner of the finest level's smoother, a PCSHELL. Row r of PETSc's vectors is
  /// DOF method_of_row[r] (every row's, #dofs). Collective over several ranks. Returns
  /// PETSc's error code (0: done).
  PetscErrorCode install(PC pc, const Eigen::SparseMatrix<double>& matrix, std::vector<Eigen::Index> method_of_row,
                         bool matrix_is_share = false);

private:
  bool over_ranks_ = false;
  bool bounds_chosen_ = false;  // the options choose the Chebyshev bounds
  PreconditionerFactory factory_;
  std::unique_ptr<Preconditioner> preconditioner_;
  std::vector<Eigen::Index> method_of_row_;
};

}  // namespace altfem
#endif
