#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// A structured mesh of an axis-aligned box with resolution (nx, ny, nz) cells of any
/// element type. Tetrahedral types split every grid cube into the six tetrahedra of
/// Kuhn's triangulation around its main diagonal, which is conforming across cubes.
/// Higher-order nodes are placed on straight edges (elevate_order).
VolumeMesh structured_grid(const Eigen::AlignedBox3d& box, const Eigen::Vector3i& resolution, ElementType type);

}  // namespace altfem
