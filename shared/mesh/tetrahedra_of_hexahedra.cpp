#include "shared/mesh/tetrahedra_of_hexahedra.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <string>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/element/element_faces.hpp"

namespace altfem {

VolumeMesh tetrahedra_of_hexahedra(const VolumeMesh& hexahedra) {
  if (element_shape(hexahedra.element_type) != ElementShape::hexahedron)
    throw std::logic_error("tetrahedra_of_hexahedra: the mesh is not hexahedral");
  const Eigen::Index cell_count = hexahedra.cells.rows();
  // Corner nodes keep their order; nodes only higher-order cells use are dropped.
  std::vector<int> new_index(hexahedra.nodes.rows(), -1);
  int corner_count = 0;
  for (Eigen::Index cell = 0; cell < cell_count; ++cell)
    for (int corner = 0; corner < 8; ++corner) new_index[hexahedra.cells(cell, corner)] = 0;
  for (int& index : new_index)
    if (index == 0) index = corner_count++;

  VolumeMesh tetrahedra;
  tetrahedra.element_type = ElementType::tet4;
  tetrahedra.nodes.resize(corner_count + cell_count, 3);
  for (Eigen::Index node = 0; node < hexahedra.nodes.rows(); ++node)
    if (new_index[node] >= 0) tetrahedra.nodes.row(new_index[node]) = hexahedra.nodes.row(node);
  tetrahedra.cells.resize(12 * cell_count, 4);

  for (Eigen::Index cell = 0; cell < cell_count; ++cell) {
    const int centre = corner_count + static_cast<int>(cell);
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for (int corner = 0; corner < 8; ++corner) centroid += hexahedra.nodes.row(hexahedra.cells(cell, corner));
    tetrahedra.nodes.row(centre) = centroid / 8.0;
    int row = 12 * static_cast<int>(cell);
    for (const auto& face : hexahedron_faces) {
      int global[4];
      for (int k = 0; k < 4; ++k) global[k] = hexahedra.cells(cell, face[k]);
      const int first = static_cast<int>(std::min_element(global, global + 4) - global);
      // Outward counter-clockwise corners a, b, c, d from the smallest: triangles (a, b, c)
      // and (a, c, d); with the centroid behind them, (a, c, b, centre) is positive.
      const int a = new_index[global[first]], b = new_index[global[(first + 1) % 4]],
                c = new_index[global[(first + 2) % 4]], d = new_index[global[(first + 3) % 4]];
      tetrahedra.cells.row(row++) << a, c, b, centre;
      tetrahedra.cells.row(row++) << a, d, c, centre;
    }
    for (int tetrahedron = 12 * static_cast<int>(cell); tetrahedron < row; ++tetrahedron) {
      const auto corner = [&](int k) -> Eigen::Vector3d {
        return tetrahedra.nodes.row(tetrahedra.cells(tetrahedron, k)).transpose();
      };
      const double six_volume = (corner(1) - corner(0)).cross(corner(2) - corner(0)).dot(corner(3) - corner(0));
      if (!(six_volume > 0))
        throw InputError("hexahedron " + std::to_string(cell) +
                         " is not star-shaped about its corner centroid: it has no tetrahedra of positive volume "
                         "from it");
    }
  }
  return tetrahedra;
}

}  // namespace altfem
