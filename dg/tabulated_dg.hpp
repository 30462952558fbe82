#pragma once
// DG for every material model (beyond Kaufmann et al. 2009, whose §4 is linear): the
// monomials of a DgLinearSystem tabulated at points of a rule on each polyhedron
// (DgLinearSystem::cell_rule: exact for polynomials up to its strength) for the shared assembly,
// which evaluates any hyperelastic ψ(F). The faces carry the jump penalty
// η_f/2 ∫ |[[u]]|² (eq. (19), shared JumpPenaltyKernel), interior and Dirichlet faces alike.
// With the Babuška–Zlámal flux that is all (eq. (19): inconsistent, its error does not
// vanish with h at a fixed η). With the interior-penalty flux, each cell's volume points
// see the lifted DG gradient of Ten Eyck & Lew 2006 (dg/lifted_gradients.hpp), whose
// Euler–Lagrange equation holds the average first Piola–Kirchhoff stress on every face:
// the consistent interior-penalty method of any material, with an exact symmetric Hessian.
#include <memory>

#include "dg/dg_linear_system.hpp"
#include "dg/lifted_gradients.hpp"
#include "shared/assembly/tabulated_discretization.hpp"
#include "shared/assembly/tabulated_faces.hpp"

namespace altfem::dg {

struct TabulatedDg {
  /// The interior-penalty flux's lifted Dirichlet data (read at every set_time): before the discretization.
  std::unique_ptr<LiftedDirichletData> lifted_data;
  std::unique_ptr<TabulatedDiscretization> discretization;
};

/// Every cell's monomials at the points of system.cell_rule(cell, strength), each cell with
/// its system.material_id; the points' positions (#points × 3, in packed order) into
/// `points` when it is given. A cell `here` does not hold is added with its functions and
/// its rule's point count only (TabulatedElements::add_held_elsewhere), the count taken from
/// `listed` (every cell's, ElementTabulator) when it is given, else from the rule.
TabulatedElements tabulate_dg_cells(const DgLinearSystem& system, int strength, Eigen::MatrixXd* points = nullptr,
                                    const TabulatedHere& here = nullptr, const TabulatedElements* listed = nullptr);

/// The discretization of `system`'s cells and faces (its bases, flux, penalties and
/// Dirichlet faces) with `materials` (not owned; cell c takes materials[system.material_id(c)]);
/// the rule strength is 2k (mass and body-force loads exact). external_force: the weak
/// conditions' data load at a time (with the interior-penalty flux: the penalty's part
/// alone, DgLinearSystem::dirichlet_load with penalty_only); data: with the
/// interior-penalty flux, the Dirichlet data the lifting shifts F by at each set_time
/// (empty: g = 0); preconditioner: block Jacobi; strong: the coefficients the strongly
/// imposed conditions fix (dg/strong_conditions.hpp; their faces carry no term), empty
/// when every condition is weak; coarse_space: PETSc's coarse level
/// (multigrid_coarse_space.hpp), empty for none.
TabulatedDg make_tabulated_dg(const DgLinearSystem& system, std::vector<const Material*> materials,
                              std::function<Eigen::VectorXd(double)> external_force,
                              PreconditionerFactory preconditioner, ConditionTrajectory data = {},
                              DirichletDofs strong = {}, CoarseSpace coarse_space = {});

}  // namespace altfem::dg
