#pragma once
// The cells of a polyhedral mesh near a box, taken out as a mesh of their own and, once
// cut, put back (cut_by_surface.hpp). A surface blade's triangle is cut in up to five
// planar steps, each over the whole mesh it was given; the pieces of every triangle before
// stay apart until the end, so on the whole mesh a blade of n triangles costs n times a
// mesh that grows with n (the 320-triangle ball cut out of a 4³ grid: 50,000 pieces by
// its last triangles, two minutes). Its steps split only the cells whose bounding box
// meets the triangle's, and put crossing nodes on the faces of the cells that share those
// cells' edges; the window holds both — the cells the triangle's box meets and every cell
// sharing a node with one of them — so its steps on the window make the same pieces, nodes
// and faces as on the whole mesh.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem {

struct PolyhedralMeshWindow {
  /// The window's cells (in the order of the whole mesh), their faces (a face with a cell
  /// outside oriented for the one inside, its other cell −1) and their nodes (renumbered in
  /// the order of the whole mesh). Geometry arrays empty.
  PolyhedralMesh mesh;
  std::vector<int> cells;  ///< per window cell: its cell in the whole mesh
  std::vector<int> nodes;  ///< per window node: its node in the whole mesh
  /// The faces between a window cell and a cell outside: per such face, its index in the
  /// whole mesh and in the window. No cut of the window changes them (their cells share no
  /// node with a cell the box meets).
  std::vector<int> shell_faces, shell_window_faces;
};

/// The window of `mesh` about `box` (`cell_boxes`: #cells, each cell's nodes' bounding
/// box): no cells when no cell's box meets it.
PolyhedralMeshWindow polyhedral_mesh_window(const PolyhedralMesh& mesh,
                                            const std::vector<Eigen::AlignedBox3d>& cell_boxes,
                                            const Eigen::AlignedBox3d& box);

/// Puts `cut` — the window's mesh cut, `cut_parent` per cell of it its window cell; its
/// first window.nodes.size() nodes the window's, the rest new — back into `mesh` in place of
/// the window's cells: each cell's pieces where it was, in its order; new nodes appended
/// (the whole mesh's nodes keep their numbers); `cell_boxes` and `parent_cell` (per cell, a
/// cell of the input before any window) follow. Geometry arrays emptied. Throws
/// std::logic_error when the cut changed a shell face or split a cell next to one.
void splice_polyhedral_mesh_window(PolyhedralMesh& mesh, std::vector<Eigen::AlignedBox3d>& cell_boxes,
                                   std::vector<int>& parent_cell, const PolyhedralMeshWindow& window,
                                   PolyhedralMesh&& cut, const std::vector<int>& cut_parent);

/// The bounding box of each cell's nodes: #cells.
std::vector<Eigen::AlignedBox3d> polyhedral_cell_boxes(const PolyhedralMesh& mesh);

}  // namespace altfem
