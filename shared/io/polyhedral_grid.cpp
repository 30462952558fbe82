#include "shared/io/polyhedral_grid.hpp"

#include <algorithm>

namespace altfem {

UnstructuredGrid grid_from_polyhedral_mesh(const PolyhedralMesh& mesh) {
  UnstructuredGrid grid;
  grid.points = mesh.nodes;
  const int cell_count = mesh.cell_count();
  Eigen::MatrixXd kinds(cell_count, 1);
  std::vector<std::vector<int64_t>> faces;
  for (int cell = 0; cell < cell_count; ++cell) {
    faces.clear();
    for (int face : mesh.cell_faces[cell]) {
      std::vector<int64_t> loop(mesh.faces[face].begin(), mesh.faces[face].end());
      // Stored loops are outward for face_cells(f, 0); VTK wants each cell's outward loop.
      if (mesh.face_cells(face, 0) != cell) std::reverse(loop.begin(), loop.end());
      faces.push_back(std::move(loop));
    }
    grid.add_polyhedron(faces);
    kinds(cell, 0) = static_cast<double>(mesh.cell_kinds[cell]);
  }
  grid.cell_data.emplace_back("volume", mesh.cell_volumes);
  grid.cell_data.emplace_back("kind", std::move(kinds));
  return grid;
}

}  // namespace altfem
