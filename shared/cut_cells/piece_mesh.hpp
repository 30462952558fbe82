#pragma once
// The background mesh of topology-aware finite cells: one cell per connected piece of
// material in each background cell (cell_pieces.hpp), and one copy of a background node
// per connected part of the material around it. A node's copies are the components of
// the pieces of the cells that hold the node, joined where the material continues
// across a face between two of those cells (the node's star: the usual rule of cut
// finite elements for cells with disconnected parts of the domain).
// Copies share their node's position: every downstream part (quadrature, assembly,
// Dirichlet conditions, Schwarz blocks, output) sees an ordinary Lagrange mesh.
#include <vector>

#include "shared/cut_cells/cell_pieces.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

struct PieceMesh {
  /// One cell per piece of every background cell with material, and each cell without
  /// material once (with no tetrahedra, so it stays outside), in background order.
  /// Nodes: the copies, at their background node's position.
  VolumeMesh mesh;
  std::vector<int> background_cell;          ///< per cell: its background cell
  std::vector<int> piece;                    ///< per cell: its piece index within the background cell
  std::vector<std::vector<int>> tetrahedra;  ///< per cell: the embedded tetrahedra it clips
  std::vector<char> filled;                  ///< per cell: 1 where the material fills it (CellPieces::filled)
  std::vector<int> background_node;          ///< per node: the background node it copies

  /// Background nodes with two or more copies.
  int split_nodes() const;
};

/// The piece mesh of `background` with its `pieces` (find_cell_pieces).
PieceMesh piece_mesh(const VolumeMesh& background, const CellPieces& pieces);

}  // namespace altfem
