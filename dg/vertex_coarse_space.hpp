#pragma once
// The coarse space of DG's two-level preconditioner (shared/solve/two_level_preconditioner.hpp)
// on an arbitrary polyhedral mesh: continuous vector fields given by their values at the
// mesh's vertices, each element taking the least-squares affine fit of its own vertices'
// values — on a simplicial mesh exactly the continuous piecewise-linear space of Dobrev,
// Lazarov, Vassilevski & Zikatanov 2006 (§3), on other cells its natural generalisation (the
// fit Kaufmann et al. 2009 §6.1 uses for the warping's rotations, at the vertices).
//
// Every element's fit is well-posed: a cell of positive volume has four vertices off a
// common plane. Cut cells of sliced meshes have many vertices, some of the cut surface shared
// only with neighbouring cut pieces; each is a coarse vertex like any other, and the fit,
// centred and scaled like the element's monomials, reproduces affine fields exactly whatever
// their number. Fields whose fit vanishes on every element (hourglass patterns of hexahedra,
// surplus vertices of cut cells) make P's columns dependent; the two-level preconditioner
// shifts its coarse matrix for them.
#include <Eigen/SparseCore>

#include "dg/dg_linear_system.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem::dg {

struct VertexCoarseSpace {
  /// P: #dofs × 3 · #vertices; column 3v + i is the unit value of component i at vertex v;
  /// row 3a + i the coefficient of component i of function a (its cell's numbering as in
  /// DgLinearSystem). Only the constant and linear monomials have non-zero rows, except in
  /// cells whose functions are combinations of monomials (strong conditions).
  Eigen::SparseMatrix<double> prolongation;
  /// The mesh node of each coarse vertex (#vertices): the nodes of at least one cell.
  std::vector<int> nodes;
};

/// The coarse space of `mesh`, whose cells are `system`'s (same order). Throws
/// NumericalError naming a cell whose vertices lie in a plane (a degenerate cell).
VertexCoarseSpace vertex_coarse_space(const PolyhedralMesh& mesh, const DgLinearSystem& system);

}  // namespace altfem::dg
