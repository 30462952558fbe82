#pragma once
// GAMG on a method's first-order space as the coarse level of a two-level multigrid
// whose fine level is the method's own higher-order space (a p-multigrid), on one
// process or over several ranks. Smoothed aggregation builds its coarse spaces from the matrix graph: a Hex20
// or Tet10 node's neighbourhood is not a mesh neighbourhood, and CG + GAMG took 45-60
// iterations on quadratic cantilevers against 23-28 on Hex8 (docs/performance.md). On
// the first-order space, Pᵀ A P with P the interpolation of first-order functions
// (shared/fem/first_order_space.hpp), GAMG sees a first-order operator; the fine level's
// smoother (Chebyshev on the diagonal, or the method's own: fcm's Additive Schwarz)
// removes what the first-order space cannot hold.
#ifdef ALTFEM_HAVE_PETSC
#include <petscksp.h>

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <string>
#include <vector>

#include "shared/solve/coarse_space.hpp"

namespace altfem {

class FirstOrderCoarseLevel {
public:
  /// `space`: the coarse functions in the method's basis (empty: nothing is done);
  /// `near_null_space`: the method's rigid-body modes (#dofs × 6, or empty), whose
  /// values at the coarse functions' nodes span the coarse operator's near-null space.
  FirstOrderCoarseLevel(CoarseSpace space, const Eigen::MatrixXd& near_null_space);
  ~FirstOrderCoarseLevel();
  FirstOrderCoarseLevel(const FirstOrderCoarseLevel&) = delete;
  FirstOrderCoarseLevel& operator=(const FirstOrderCoarseLevel&) = delete;

  /// After the options are read: when `pc` is GAMG, makes it a two-level PCMG (levels'
  /// options under the prefix "mg_levels_", the coarse level's, a GAMG, under
  /// "mg_coarse_", which coarsens its finest level aggressively only with
  /// `aggressive_coarsening` and not the space's coarsen_gently, or where the options
  /// choose); any other preconditioner is left
  /// alone. Returns PETSc's error code.
  PetscErrorCode configure(PC pc, bool aggressive_coarsening = true);
  /// Where the fine operator's rows are: PETSc's row of each DOF (empty: the DOF's own
  /// index) and this rank's rows [first_row, last_row) of `communicator`'s matrix.
  struct Rows {
    const std::vector<PetscInt>& petsc_of_method;
    PetscInt first_row = 0, last_row = 0;
    MPI_Comm communicator = PETSC_COMM_SELF;
  };
  /// Before every set-up of `pc`, with `matrix` (the method's numbering, both triangles;
  /// over several ranks this rank's share or copy of it) and `fine` (PETSc's) the fine
  /// operator: the coarse operator Pᵀ A P. A DOF whose row couples to no other (a
  /// Dirichlet condition's, eliminated: dirichlet_elimination.hpp) is left out of the
  /// other DOFs' coarse functions, so the coarse level never moves it. Over several ranks
  /// a coarse function's rows belong to the rank owning its node's. Returns PETSc's
  /// error code.
  PetscErrorCode update(PC pc, Mat fine, const Eigen::SparseMatrix<double>& matrix, const Rows& rows);

private:
  /// This rank's rows of the interpolation at DOF level (#dofs × 3·#coarse functions),
  /// given which DOFs are decoupled; numbers the coarse functions rank by rank.
  PetscErrorCode build_interpolation(const std::vector<char>& decoupled, const Rows& rows);
  PetscErrorCode set_coarse_near_null_space();

  CoarseSpace space_;
  Eigen::MatrixXd near_null_space_at_nodes_;             // 3·#coarse functions × 6 (coarse order), or empty
  std::vector<PetscInt> coarse_row_;                     // #coarse functions: PETSc's first row of each
  PetscInt first_coarse_row_ = 0, last_coarse_row_ = 0;  // this rank's coarse rows
  std::string gentle_option_;    // the coarse GAMG's "-…pc_gamg_aggressive_coarsening 0" set here, cleared with it
  bool active_ = false;          // configure() made the preconditioner a two-level PCMG
  std::vector<char> decoupled_;  // #dofs: the decoupled DOFs interpolation_ was built for
  Mat interpolation_ = nullptr;
  Mat coarse_ = nullptr;
  PetscObjectId fine_id_ = 0;  // the fine matrix coarse_ was made from
};

}  // namespace altfem
#endif
