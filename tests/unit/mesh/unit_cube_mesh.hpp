#pragma once
// The mesh the cut and split tests start from: the unit cube as a polyhedral mesh of
// cells_per_axis³ cells of one element type.
#include <Eigen/Geometry>

#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem {

inline PolyhedralMesh unit_cube_mesh(ElementType type, int cells_per_axis) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  return polyhedral_mesh_from_volume_mesh(structured_grid(box, Eigen::Vector3i::Constant(cells_per_axis), type));
}

}  // namespace altfem
