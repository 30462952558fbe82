#include "shared/io/unstructured_grid.hpp"

#include <algorithm>
#include <stdexcept>

namespace altfem {

void UnstructuredGrid::add_cell(int vtk_type, std::span<const int64_t> point_ids,
                                std::vector<std::vector<int64_t>> faces) {
  // Keep polyhedron_faces aligned with the cells even if it was left empty by a
  // caller that filled the arrays directly.
  polyhedron_faces.resize(cell_types.size());
  cell_types.push_back(vtk_type);
  connectivity.insert(connectivity.end(), point_ids.begin(), point_ids.end());
  offsets.push_back(static_cast<int64_t>(connectivity.size()));
  polyhedron_faces.push_back(std::move(faces));
}

void UnstructuredGrid::add_cells(ElementType type, const Eigen::MatrixXi& cells) {
  if (cells.cols() != element_node_count(type))
    throw std::invalid_argument("add_cells: " + std::string(element_name(type)) + " cells need " +
                                std::to_string(element_node_count(type)) + " columns, got " +
                                std::to_string(cells.cols()));
  std::vector<int64_t> ids(static_cast<std::size_t>(cells.cols()));
  for (Eigen::Index cell = 0; cell < cells.rows(); ++cell) {
    for (Eigen::Index node = 0; node < cells.cols(); ++node) ids[node] = cells(cell, node);
    add_cell(element_vtk_cell_type(type), ids);
  }
}

void UnstructuredGrid::add_triangles(const Eigen::MatrixXi& triangles) {
  if (triangles.cols() != 3)
    throw std::invalid_argument("add_triangles: triangles need 3 columns, got " + std::to_string(triangles.cols()));
  for (Eigen::Index triangle = 0; triangle < triangles.rows(); ++triangle) {
    const int64_t ids[3] = {triangles(triangle, 0), triangles(triangle, 1), triangles(triangle, 2)};
    add_cell(vtk_triangle, ids);
  }
}

void UnstructuredGrid::add_polyhedron(const std::vector<std::vector<int64_t>>& faces) {
  if (faces.size() < 4) throw std::invalid_argument("add_polyhedron: a polyhedron needs at least 4 faces");
  std::vector<int64_t> distinct;
  for (const auto& face : faces) {
    if (face.size() < 3) throw std::invalid_argument("add_polyhedron: a face needs at least 3 points");
    for (const int64_t id : face)
      if (std::find(distinct.begin(), distinct.end(), id) == distinct.end()) distinct.push_back(id);
  }
  add_cell(vtk_polyhedron, distinct, faces);
}

UnstructuredGrid grid_from_volume_mesh(const VolumeMesh& mesh) {
  UnstructuredGrid grid;
  grid.points = mesh.nodes;
  grid.add_cells(mesh.element_type, mesh.cells);
  return grid;
}

}  // namespace altfem
