#pragma once
// A DG field carried across an event that changed the mesh (docs/architecture.md,
// "Events"; Kaufmann et al. 2009 §9.3–9.4 copy the parent's polynomial into its pieces).
#include <Eigen/Core>

#include "dg/dg_linear_system.hpp"
#include "shared/simulation/basis_embedding.hpp"

namespace altfem::dg {

/// The coefficients in `system`'s basis (#dofs × #fields) of fields of `previous` (the
/// columns of `fields`, #dofs of previous × #fields, evaluated through `previous_basis`). A cell whose vertices and
/// functions (monomials and their combination) are those of the same-numbered cell
/// before keeps its coefficients bit for bit; any other gets the L2 projection of the old field on its polynomials by a
/// rule of strength 2k, which is the parent polynomial restricted to it (exact to round-off) when the cell lies inside
/// one old cell.
Eigen::MatrixXd transfer_dg_field(const DgLinearSystem& system, const DgLinearSystem& previous,
                                  const ElementBasisEvaluator& previous_basis, const Eigen::MatrixXd& fields);

}  // namespace altfem::dg
