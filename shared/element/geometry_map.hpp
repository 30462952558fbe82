#pragma once
// The isoparametric geometry map of one element, x(ξ) = Σ_i N_i(ξ) x_i, its
// Jacobian, and its inverse (point location in an element, embedding).
#include <Eigen/Core>
#include <optional>

#include "shared/element/reference_element.hpp"

namespace altfem {

/// x(ξ) = Σ_i N_i(ξ) x_i; element_nodes is #nodes × 3 (row i = x_i, VTK order).
Eigen::Vector3d map_to_physical(const ReferenceElement& element, const Eigen::Ref<const Eigen::MatrixXd>& element_nodes,
                                const Eigen::Vector3d& xi);

/// J_ij = ∂x_i/∂ξ_j at ξ (3 × 3); element_nodes is #nodes × 3.
Eigen::Matrix3d map_jacobian(const ReferenceElement& element, const Eigen::Ref<const Eigen::MatrixXd>& element_nodes,
                             const Eigen::Vector3d& xi);

/// The constant Jacobian when the map is affine (x(ξ) = x(ξ_c) + J (ξ − ξ_c), every node
/// within 1e-12 × the element's extent of it), else nothing. The nodes determine the map,
/// so then J holds at every point of the element: a rule of many points needs no
/// gradients there (the grids' cells, straight tetrahedra).
std::optional<Eigen::Matrix3d> affine_jacobian(const ReferenceElement& element,
                                               const Eigen::Ref<const Eigen::MatrixXd>& element_nodes);

struct InverseMapResult {
  Eigen::Vector3d xi;  ///< the reference point found (extrapolated when outside)
  bool converged;      ///< Newton met the tolerance
  bool inside;         ///< converged and ξ in the reference domain (slack max(tolerance, 1e-10))
  int iterations;      ///< Newton steps before the step fell below tolerance (1 if affine)
  double residual;     ///< ‖x(ξ) − x‖, physical units
};

/// Solves x(ξ) = x by damped Newton from the reference centroid: each step solves
/// J Δξ = x − x(ξ) and is halved until ‖x(ξ) − x‖ decreases (at most 30 halvings).
/// Converged once the Newton step is at most `tolerance` in every reference
/// coordinate (that last step is applied too, so ξ is accurate well beyond it);
/// an affine map is inverted by the first, full step. A point outside the element
/// gives inside = false; ξ is still the extrapolated solution when Newton converges
/// (embedding uses it). converged = false (no throw) on a singular Jacobian, a
/// failed line search or max_iterations steps, with ξ the last iterate: the caller
/// decides what a failure means in its context.
InverseMapResult map_to_reference(const ReferenceElement& element,
                                  const Eigen::Ref<const Eigen::MatrixXd>& element_nodes, const Eigen::Vector3d& x,
                                  double tolerance = 1e-12, int max_iterations = 50);

}  // namespace altfem
