#include "shared/cut_cells/piece_dirichlet.hpp"

#include <algorithm>
#include <memory>

#include "shared/cut_cells/cut_cell_rule.hpp"

namespace altfem {

namespace {

/// Whether the part of `tetrahedra` in the cell has a vertex in the region.
bool material_reaches(const CellGeometry& cell, const VolumeMesh& embedded, const std::vector<int>& tetrahedra,
                      const RegionSelector& region, double tolerance) {
  TetrahedronCorners corners;
  for (const int t : tetrahedra) {
    for (int i = 0; i < 4; ++i) corners.row(i) = embedded.nodes.row(embedded.cells(t, i));
    for (const TetrahedronCorners& piece : clip_tetrahedron(corners, cell.planes()))
      for (int i = 0; i < 4; ++i)
        if (region.contains(piece.row(i).transpose(), tolerance)) return true;
  }
  return false;
}

}  // namespace

NodeRegionFilter piece_dirichlet_nodes(const PieceMesh& pieces, const VolumeMesh& embedded) {
  struct Data {
    VolumeMesh mesh, embedded;
    std::vector<std::vector<int>> tetrahedra;
    std::vector<std::vector<int>> cells_of_copy;  ///< per node with sibling copies: its cells with material; else empty
  };
  auto data = std::make_shared<Data>(Data{pieces.mesh, embedded, pieces.tetrahedra, {}});
  std::vector<int> copies(pieces.background_node.empty()
                              ? 0
                              : *std::max_element(pieces.background_node.begin(), pieces.background_node.end()) + 1);
  for (const int node : pieces.background_node) ++copies[node];
  data->cells_of_copy.resize(pieces.background_node.size());
  for (Eigen::Index cell = 0; cell < pieces.mesh.cells.rows(); ++cell) {
    if (pieces.tetrahedra[cell].empty()) continue;
    for (Eigen::Index a = 0; a < pieces.mesh.cells.cols(); ++a) {
      const int node = pieces.mesh.cells(cell, a);
      if (copies[pieces.background_node[node]] > 1) data->cells_of_copy[node].push_back(static_cast<int>(cell));
    }
  }
  return [data](int node, const RegionSelector& region, double tolerance) {
    const std::vector<int>& cells = data->cells_of_copy[node];
    if (cells.empty()) return true;
    const int corner_count = element_corner_count(data->mesh.element_type);
    Eigen::MatrixXd corners(corner_count, 3);
    return std::any_of(cells.begin(), cells.end(), [&](int cell) {
      for (int i = 0; i < corner_count; ++i) corners.row(i) = data->mesh.nodes.row(data->mesh.cells(cell, i));
      return material_reaches(CellGeometry(data->mesh.element_type, corners), data->embedded, data->tetrahedra[cell],
                              region, tolerance);
    });
  };
}

}  // namespace altfem
