#pragma once
// A method's own preconditioner as the smoother of the finest level of PETSc's algebraic
// multigrid, on one process. fcm's cut cells leave functions whose support holds a
// sliver of material: their energy is tiny and local, so neither GAMG's point smoother
// (Chebyshev on the diagonal) nor its coarse spaces (smooth aggregates) reduce it, and CG
// takes about 1,100 iterations on the half-ball's 8 × 8 × 4 Hex20 grid (89 with this). The
// Additive Schwarz blocks of the small cut cells (Longva et al. 2020 §5.2) invert exactly
// that energy; as the fine smoother they leave GAMG the smooth error it reduces well.
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
  /// `factory`: the method's preconditioner (empty: none, and nothing is done).
  explicit FinestLevelSmoother(PreconditionerFactory factory) : factory_(std::move(factory)) {}
  /// Whether there is a preconditioner to install.
  explicit operator bool() const { return static_cast<bool>(factory_); }

  /// Before the first set-up of `pc` (its type read from the options): with GAMG, every
  /// level's Chebyshev iteration estimates its own eigenvalue bounds, since the finest one
  /// must bound the spectrum the method's preconditioner leaves, not the Jacobi-smoothed
  /// one GAMG's aggregation estimates (97 iterations on the half-ball with those, 89 with
  /// its own) — unless `petsc_options` choose (-pc_gamg_use_sa_esteig).
  PetscErrorCode configure(PC pc, const std::string& petsc_options) const;

  /// After every set-up of `pc` (a PCMG or PCGAMG; any other is left alone) on `matrix`
  /// (the method's numbering): the method's preconditioner computed on it becomes the
  /// preconditioner of the finest level's smoother, a PCSHELL. Row r of PETSc's vectors is
  /// DOF method_of_row[r]. Returns PETSc's error code (0: done).
  PetscErrorCode install(PC pc, const Eigen::SparseMatrix<double>& matrix, std::vector<Eigen::Index> method_of_row);

private:
  PreconditionerFactory factory_;
  std::unique_ptr<Preconditioner> preconditioner_;
  std::vector<Eigen::Index> method_of_row_;
};

}  // namespace altfem
#endif
