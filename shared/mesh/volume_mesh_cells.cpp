#include "shared/mesh/volume_mesh_cells.hpp"

namespace altfem {

VolumeMesh volume_mesh_cells(const VolumeMesh& mesh, const std::vector<int>& cells) {
  std::vector<int> new_index(static_cast<std::size_t>(mesh.nodes.rows()), -1);
  VolumeMesh result{mesh.element_type, {}, Eigen::MatrixXi(static_cast<Eigen::Index>(cells.size()), mesh.cells.cols())};
  int nodes = 0;
  for (std::size_t i = 0; i < cells.size(); ++i)
    for (Eigen::Index k = 0; k < mesh.cells.cols(); ++k) {
      int& index = new_index[mesh.cells(cells[i], k)];
      if (index < 0) index = nodes++;
      result.cells(static_cast<Eigen::Index>(i), k) = index;
    }
  result.nodes.resize(nodes, 3);
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node)
    if (new_index[node] >= 0) result.nodes.row(new_index[node]) = mesh.nodes.row(node);
  return result;
}

}  // namespace altfem
