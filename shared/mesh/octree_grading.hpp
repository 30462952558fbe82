#pragma once
// Octree grading without hanging nodes (Martin et al. 2008, §7 and Fig. 4): grid cells
// wholly inside the object, away from its surface, are joined into 2^L-sized octree cells
// with a 2:1 balance; a coarse cell next to finer ones is a polyhedron whose faces carry
// the finer neighbours' nodes, so the mesh stays conforming without constraint equations.
#include <Eigen/Core>
#include <vector>

#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

/// Joins the hexahedra of `mesh` into octree cells of up to 2^max_level grid cells per side.
/// `grid_cells`: the grid's cells per axis; `grid_hexahedra`: per grid cell (index
/// i + nx (j + ny k)), the mesh cell of the hexahedron filling it, or −1 (cut or outside).
/// An aligned block of level L becomes one cell (kind `coarse`) when every grid cell within
/// 2^(L+1) cells of it is such a hexahedron; the largest such blocks are taken, which keeps
/// neighbouring cells within one level of each other. Coplanar faces between the same two
/// cells become one polygon, and a node left on a straight edge of every face that uses it
/// is removed. Needs no geometry and leaves it stale (call compute_polyhedral_geometry).
/// Returns the number of coarse cells.
int grade_interior_hexahedra(PolyhedralMesh& mesh, const Eigen::Vector3i& grid_cells,
                             const std::vector<int>& grid_hexahedra, int max_level);

}  // namespace altfem
