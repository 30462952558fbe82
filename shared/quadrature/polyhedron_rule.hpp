#pragma once
// A quadrature rule on any polyhedron with planar faces (DG's nonlinear path, harmonic
// elements): a cone decomposition from an apex — each face cut into triangles (ear clipping), each
// triangle with the apex a tetrahedron carrying a tet rule — exact to the requested
// strength for every closed polyhedron, because the signed tetrahedra add up to the
// polyhedron as a chain (divergence theorem). The apex is the centroid, or when that does
// not see every face from inside, the centre of the polyhedron's kernel
// (polyhedron_kernel_point): so every star-shaped cell (every convex cell, and most cut
// cells) gets positive weights. Otherwise some tetrahedra are inverted and carry negative
// weights, which integrate exactly but are no rule a positive-weight simplifier may start
// from, nor one that keeps a lumped mass positive.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

#include "shared/geometry/polyhedron.hpp"
#include "shared/quadrature/simplify_quadrature.hpp"

namespace altfem {

struct PolyhedronRule {
  Eigen::MatrixXd points;   ///< #points × 3, physical
  Eigen::VectorXd weights;  ///< #points, summing to the volume
  bool positive = true;     ///< every weight > 0
};

/// Triangles (index triples into `face`, in its orientation) of a simple planar polygon
/// (face: indices of `vertices` rows, convex or not), by ear clipping in its plane.
std::vector<std::array<int, 3>> triangulate_face(const Eigen::MatrixXd& vertices, const std::vector<int>& face);

/// A rule on a planar polygon in 3D (polygon: #vertices × 3, simple, convex or not):
/// the triangle rule of `strength` on the triangles of its ear clipping. Exact to the
/// strength; weights positive (they sum to the area).
PolyhedronRule polygon_rule(const Eigen::MatrixXd& polygon, int strength);

/// The rule of `strength` (tet_rule) on each cone tetrahedron about the centroid (or the kernel point). Throws
/// std::invalid_argument for a polyhedron without faces. A cell star-shaped about no point
/// gets positive weights on points inside it that integrate every polynomial of degree
/// `strength` as the cone rule does: at most C(strength + 3, 3) of them, or, with
/// `minimum_points` > 0, at least that many (when the cone rule has them inside the cell),
/// for integrands that are not polynomials and need the points (harmonic bases).
PolyhedronRule polyhedron_rule(const Polyhedron& polyhedron, int strength, int minimum_points = 0);

/// polyhedron_rule(polyhedron, strength) with at most C(strength + 3, 3) points: the cone
/// rule of a cell bounded by many facets (a cut cell of a detailed surface carries one
/// tetrahedron per facet triangle) simplified by simplify_quadrature with `method` at
/// degree `strength`, so it integrates every polynomial of that degree as the cone rule
/// does (to simplify_quadrature's default tolerance; Longva et al. 2020 §4.4, the FCM's
/// cut-cell rules). The cone rule as it is when `method` is nullopt (a scene's simplifier
/// `none`), has negative weights, or the simplifier fails on it.
PolyhedronRule simplified_polyhedron_rule(const Polyhedron& polyhedron, int strength,
                                          std::optional<SimplificationMethod> method, int minimum_points = 0);

}  // namespace altfem
