#pragma once
// Exact integrals of every monomial up to a degree over a polyhedron with planar
// polygonal faces, convex or not, by the divergence theorem (Mirtich 1996; Kaufmann et
// al. 2009, Sec. 5 and Appendix A), here in the homogeneous-function form of Chin,
// Lasserre & Sukumar (2015) that needs neither triangulated faces nor degree-specific
// formulas. Used for DG mass and stiffness integrals over polyhedral elements.
#include <Eigen/Core>

#include "shared/geometry/polyhedron.hpp"

namespace altfem {

/// ∫_P x^a y^b z^c dV for every a+b+c <= degree, in monomial_index order (length
/// monomial_count(degree)). Computed about the centre of P's bounding box, scaled by its
/// size, then shifted back, so a small polyhedron far from the origin keeps full relative
/// accuracy. Faces must close the surface and be counter-clockwise seen from outside (an
/// inside-out polyhedron gives the negated moments); faces of zero area are ignored.
/// Throws std::invalid_argument for degree < 0, vertices not #vertices × 3 or not finite,
/// a face with < 3 vertices or an index out of range.
Eigen::VectorXd polyhedron_moments(const Polyhedron& polyhedron, int degree);

/// ∫_P ((x−c)/s)^a ((y−c)/s)^b ((z−c)/s)^c dV (physical volume measure): the moments of a
/// monomial basis centred at `centre` and scaled by `scale` > 0 (e.g. DG's element basis).
Eigen::VectorXd polyhedron_moments(const Polyhedron& polyhedron, int degree, const Eigen::Vector3d& centre,
                                   double scale);

}  // namespace altfem
