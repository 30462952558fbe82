#pragma once
// A DG field carried across an event that changed the mesh (docs/architecture.md,
// "Events"; Kaufmann et al. 2009 §9.3–9.4 copy the parent's polynomial into its pieces).
#include <Eigen/Core>
#include <vector>

#include "dg/dg_linear_system.hpp"
#include "shared/fem/polyhedral_scene_mesh.hpp"
#include "shared/simulation/basis_embedding.hpp"

namespace altfem::dg {

/// The coefficients in `system`'s basis (#dofs × #fields) of fields of `previous` (the
/// columns of `fields`, #dofs of previous × #fields, evaluated through `previous_basis`).
/// `parent_cells` (#cells of system, or empty when unknown): the cell of previous that holds
/// each cell whole, -1 when none does. A cell with a parent gets the parent's polynomial
/// written in its own basis (exact, Kaufmann et al. 2009 §9.3: "the child inherits the
/// coefficients of the parent"); a cell whose vertices and functions (monomials and their
/// combination) are those of the same-numbered cell before keeps its coefficients bit for
/// bit; any other gets the L2 projection of the old field on its polynomials by a rule of
/// strength 2k: for a cell merged from pieces of several cells (`merged_parts`, per cell,
/// PolyhedralSceneMesh), ∫ φ u_old integrated piece by piece with each piece's parent's
/// polynomial, exactly, so that the field's integral (the momentum) is kept to round-off
/// (a rule on the whole cell straddles the parents' jump); else through `previous_basis`.
Eigen::MatrixXd transfer_dg_field(const DgLinearSystem& system, const DgLinearSystem& previous,
                                  const ElementBasisEvaluator& previous_basis, const Eigen::MatrixXd& fields,
                                  const std::vector<int>& parent_cells = {},
                                  const std::vector<std::vector<ParentPart>>& merged_parts = {});

}  // namespace altfem::dg
