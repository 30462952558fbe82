#pragma once
#include <Eigen/Core>
#include <functional>

#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// The point of the true surface nearest a given point.
using ClosestPoint = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

/// Curved (isoparametric) boundary for quadratic and cubic tetrahedra: moves every
/// higher-order node that lies on a boundary face onto the true surface, so a Tet10
/// or Tet20 mesh of a curved body approximates its boundary to the element's order
/// rather than linearly. Corner nodes stay (Mesh_3 already put them on the surface).
/// Cells that the move would fold (det J anywhere below a fifth of its straight value)
/// keep straight edges. Tetrahedral meshes only; returns how many nodes stay moved.
int curve_boundary(VolumeMesh& mesh, const ClosestPoint& closest_point);

/// Nearest point on the zero level set of `level_set` by Newton steps along the
/// (central-difference) gradient, x ← x − φ(x) ∇φ/|∇φ|²; `step` is the difference step.
Eigen::Vector3d project_to_level_set(const std::function<double(const Eigen::Vector3d&)>& level_set,
                                     const Eigen::Vector3d& x, double step);

}  // namespace altfem
