#pragma once
#include <Eigen/Geometry>

#include "shared/cut_cells/cell_quadrature.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem::fcm {

/// Exact cut-cell rules for an axis-aligned box embedded in a grid of axis-aligned
/// hexahedra (Hex8, Hex20, Hex27 of structured_grid): each cell's intersection with the
/// box is itself a box, so a tensor Gauss rule on it, mapped into the cell's reference
/// coordinates, is exact to the requested strength. This is the geometry of the
/// conditioning experiment of Longva et al. 2020 §5.4; general geometry takes the
/// intersection rules of §4.5. Throws std::invalid_argument for a tetrahedral grid or a
/// cell that is not an axis-aligned box.
CellQuadratureSource box_cell_quadrature(const VolumeMesh& grid, const Eigen::AlignedBox3d& body);

}  // namespace altfem::fcm
