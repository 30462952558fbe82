#include "dg/polyhedral_mesh_faces.hpp"

namespace altfem::dg {

std::vector<Polyhedron> mesh_cells(const PolyhedralMesh& mesh) {
  std::vector<Polyhedron> cells;
  cells.reserve(mesh.cell_count());
  for (int cell = 0; cell < mesh.cell_count(); ++cell) cells.push_back(cell_polyhedron(mesh, cell));
  return cells;
}

std::vector<DgFace> mesh_faces(const PolyhedralMesh& mesh) {
  std::vector<DgFace> faces(mesh.face_count());
  for (int f = 0; f < mesh.face_count(); ++f) {
    DgFace& face = faces[f];
    face.polygon.resize(static_cast<Eigen::Index>(mesh.faces[f].size()), 3);
    for (size_t v = 0; v < mesh.faces[f].size(); ++v) face.polygon.row(v) = mesh.nodes.row(mesh.faces[f][v]);
    face.normal = mesh.face_normals.row(f).transpose();
    face.minus = mesh.face_cells(f, 0);
    face.plus = mesh.face_cells(f, 1);
  }
  return faces;
}

}  // namespace altfem::dg
