#pragma once
// Quadrature of any degree on a polyhedral cell (DG and harmonic element integrals,
// Kaufmann et al. 2009 §5; Martin et al. 2008 §5), from a decomposition into tetrahedra
// and the project's tetrahedron rules.
#include "shared/geometry/polyhedron.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"
#include "shared/quadrature/quadrature_rule.hpp"

namespace altfem {

/// A rule on the polyhedron in physical coordinates: points #points × 3, weights #points
/// (summing to the volume), exact for every polynomial of total degree <= strength.
///
/// The decomposition is the signed cone decomposition: each face is fanned into
/// triangles from its first vertex and each triangle is joined to the centroid of the
/// polyhedron's vertices; every tetrahedron carries tet_rule(strength) scaled by its
/// SIGNED volume. By the divergence theorem the signed tetrahedra sum to the polyhedron
/// exactly for any closed, outward-oriented cell, star-shaped or not, convex faces or
/// not; degenerate (zero-volume) tetrahedra are skipped. The weights are all positive
/// exactly when every cone is positive — tetrahedra, hexahedra and convex cells (their
/// faces convex, the apex inside) — and some are negative for a cell that is not
/// star-shaped with respect to the apex, which a positive-weight rule simplifier cannot
/// take; a true (constrained) tetrahedralisation of such cells is not built yet.
/// Throws std::invalid_argument for strength < 0 or a face with < 3 vertices.
QuadratureRule polyhedron_quadrature(const Polyhedron& polyhedron, int strength);

/// polyhedron_quadrature of cell `cell` of `mesh` (cell_polyhedron).
QuadratureRule cell_quadrature(const PolyhedralMesh& mesh, int cell, int strength);

}  // namespace altfem
