#include "shared/cut_cells/piece_mesh.hpp"

#include <algorithm>

#include "shared/mesh/disjoint_sets.hpp"

namespace altfem {

int PieceMesh::split_nodes() const {
  std::vector<int> copies;
  for (const int node : background_node) {
    if (node >= static_cast<int>(copies.size())) copies.resize(static_cast<std::size_t>(node) + 1, 0);
    ++copies[node];
  }
  return static_cast<int>(std::count_if(copies.begin(), copies.end(), [](int count) { return count >= 2; }));
}

PieceMesh piece_mesh(const VolumeMesh& background, const CellPieces& pieces) {
  const int cell_count = static_cast<int>(background.cells.rows());
  const Eigen::Index nodes_per_cell = background.cells.cols();
  PieceMesh result;
  // Each background cell's first row in the piece mesh: one row per piece, one for a cell without material.
  std::vector<int> first_row(static_cast<std::size_t>(cell_count) + 1, 0);
  for (int cell = 0; cell < cell_count; ++cell)
    first_row[cell + 1] = first_row[cell] + std::max<int>(1, static_cast<int>(pieces.tetrahedra[cell].size()));
  result.mesh.element_type = background.element_type;
  result.mesh.cells.resize(first_row.back(), nodes_per_cell);
  for (int cell = 0; cell < cell_count; ++cell)
    for (int row = first_row[cell]; row < first_row[cell + 1]; ++row) {
      const int piece = row - first_row[cell];
      result.background_cell.push_back(cell);
      result.piece.push_back(piece);
      result.tetrahedra.push_back(pieces.tetrahedra[cell].empty() ? std::vector<int>{}
                                                                  : pieces.tetrahedra[cell][piece]);
      result.filled.push_back(pieces.filled[cell]);
    }

  // The star of every node: the cells with material that hold it, ascending.
  std::vector<std::vector<int>> star(static_cast<std::size_t>(background.nodes.rows()));
  for (int cell = 0; cell < cell_count; ++cell)
    if (!pieces.tetrahedra[cell].empty())
      for (Eigen::Index a = 0; a < nodes_per_cell; ++a) star[background.cells(cell, a)].push_back(cell);

  // One copy per component of the star's pieces joined across faces inside the star.
  std::vector<int> first_copy(star.size(), -1);
  std::vector<int> first_entry;
  for (int node = 0; node < static_cast<int>(star.size()); ++node) {
    const std::vector<int>& cells = star[node];
    if (cells.empty()) continue;
    first_entry.assign(1, 0);
    for (const int cell : cells)
      first_entry.push_back(first_entry.back() + static_cast<int>(pieces.tetrahedra[cell].size()));
    DisjointSets components(first_entry.back());
    for (std::size_t s = 0; s < cells.size(); ++s)
      for (std::size_t piece = 0; piece < pieces.neighbours[cells[s]].size(); ++piece)
        for (const auto& [other_cell, other_piece] : pieces.neighbours[cells[s]][piece]) {
          const auto other = std::lower_bound(cells.begin(), cells.end(), other_cell);
          if (other == cells.end() || *other != other_cell) continue;
          components.join(first_entry[s] + static_cast<int>(piece), first_entry[other - cells.begin()] + other_piece);
        }
    std::vector<int> copy_of_root(static_cast<std::size_t>(first_entry.back()), -1);
    for (std::size_t s = 0; s < cells.size(); ++s) {
      const int cell = cells[s];
      Eigen::Index local = 0;
      while (background.cells(cell, local) != node) ++local;
      for (int piece = 0; piece < first_entry[s + 1] - first_entry[s]; ++piece) {
        int& copy = copy_of_root[components.find(first_entry[s] + piece)];
        if (copy < 0) {
          copy = static_cast<int>(result.background_node.size());
          result.background_node.push_back(node);
        }
        result.mesh.cells(first_row[cell] + piece, local) = copy;
      }
    }
    first_copy[node] = copy_of_root[components.find(0)];
  }
  // Cells without material take a node's first copy, or a copy of its own.
  for (int cell = 0; cell < cell_count; ++cell) {
    if (!pieces.tetrahedra[cell].empty()) continue;
    for (Eigen::Index a = 0; a < nodes_per_cell; ++a) {
      const int node = background.cells(cell, a);
      if (first_copy[node] < 0) {
        first_copy[node] = static_cast<int>(result.background_node.size());
        result.background_node.push_back(node);
      }
      result.mesh.cells(first_row[cell], a) = first_copy[node];
    }
  }
  result.mesh.nodes.resize(static_cast<Eigen::Index>(result.background_node.size()), 3);
  for (std::size_t i = 0; i < result.background_node.size(); ++i)
    result.mesh.nodes.row(static_cast<Eigen::Index>(i)) = background.nodes.row(result.background_node[i]);
  return result;
}

}  // namespace altfem
