#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "shared/geometry/analytic_shape.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// A structured mesh of an axis-aligned box with resolution (nx, ny, nz) cells of any
/// element type. Tetrahedral types split every grid cube into the six tetrahedra of
/// Kuhn's triangulation around its main diagonal, which is conforming across cubes.
/// Higher-order nodes are placed on straight edges (elevate_order).
VolumeMesh structured_grid(const Eigen::AlignedBox3d& box, const Eigen::Vector3i& resolution, ElementType type);

/// The same over the rectilinear grid through the given planes (per axis at least two,
/// strictly increasing): cells may differ in size along each axis.
VolumeMesh rectilinear_grid(const AxisPlanes& coordinates, ElementType type);

/// The default resolution of a grid over a box with these extents (docs/scene-schema.md):
/// cells of size h = min(shortest / 2, longest / 4), n = clamp(round(extent / h), 1, 32)
/// per axis — a cube gives (4, 4, 4), a 1 × 0.1 × 0.1 beam (20, 2, 2).
Eigen::Vector3i default_grid_resolution(const Eigen::Vector3d& extent);

}  // namespace altfem
