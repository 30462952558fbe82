#pragma once
// Dirichlet conditions imposed strongly on DG's monomials (issue #18: "strongly as an
// option where it makes sense"). A monomial basis has no boundary nodes, so a condition
// u = g on a face f of cell K becomes linear constraints on K's coefficients: the trace of
// each prescribed component equals the L2 projection of g onto the traces,
//   ∫_f (u_i − g_i) m_b dA = 0 for every monomial m_b of K        (C c_i = d_i),
// stacked over K's strongly constrained faces. The constraint holds g exactly wherever g
// is a polynomial of degree ≤ k on the face (the fixed, translating, rotating and affine
// motions are affine in x). A rank-revealing QR of Cᵀ splits K's function space into r
// constrained combinations (the span of C's rows; r < n, several faces' rows are
// dependent along shared edges) and n − r free ones (C's null space). With these as K's
// functions (MonomialBasis::combine, an orthogonal change of basis) the condition fixes
// the r constrained coefficients of each prescribed component — DOFs that the shared
// integrators eliminate like fem's nodal ones — and leaves the rest free; the face
// carries no flux term.
// It makes sense where the strongly constrained faces of a cell all prescribe the same
// components (one change of basis serves them), which the dg method checks.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "dg/dg_linear_system.hpp"

namespace altfem::dg {

/// A cell with strongly constrained faces, and its change of basis.
struct StrongCell {
  int cell = 0;
  std::vector<int> faces;            ///< indices into the face list, each with `components`
  std::array<bool, 3> components{};  ///< the components its faces prescribe
  Eigen::MatrixXd combination;       ///< n × n, orthogonal: r constrained columns, then the free ones
  int constrained = 0;               ///< r
  /// r × (#faces · n): the constrained coefficients of a component from its stacked
  /// data d (d_b = ∫_f g_i m_b dA face after face), C Q₁ w = d solved by least squares.
  Eigen::MatrixXd data_map;
};

/// The change of basis of cell `cell` (its plain monomial basis `monomials`) for the
/// strongly constrained faces `face_indices` of `faces`, which must all prescribe the
/// same components (std::invalid_argument otherwise, naming the faces).
StrongCell strong_cell(int cell, const MonomialBasis& monomials, const std::vector<DgFace>& faces,
                       const std::vector<int>& face_indices);

/// The constrained coefficients of `cell` for the data g = data(condition, x): #prescribed
/// components × r, component by component (x, y, z order of the prescribed ones).
/// monomials: the cell's plain basis (the data is projected on monomials, as C is).
Eigen::MatrixXd constrained_values(const StrongCell& cell, const MonomialBasis& monomials,
                                   const std::vector<DgFace>& faces, const ConditionData& data);

}  // namespace altfem::dg
