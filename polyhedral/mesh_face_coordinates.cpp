#include "polyhedral/mesh_face_coordinates.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace altfem::harmonic {

std::vector<std::optional<FaceHarmonicCoordinates>> mesh_face_coordinates(const PolyhedralMesh& mesh,
                                                                          const std::vector<int>& cells,
                                                                          const MfsOptions& options) {
  std::vector<int> needed;
  std::vector<char> listed(static_cast<size_t>(mesh.face_count()), 0);
  for (int cell : cells)
    for (int face : mesh.cell_faces[cell])
      if (!listed[face]) listed[face] = 1, needed.push_back(face);
  std::vector<std::optional<FaceHarmonicCoordinates>> faces(static_cast<size_t>(mesh.face_count()));
  const auto count = static_cast<int>(needed.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (int k = 0; k < count; ++k) {
    const std::vector<int>& loop = mesh.faces[needed[k]];
    try {
      faces[needed[k]].emplace(mesh.nodes(loop, Eigen::all), options);
    } catch (const std::exception&) {
      // Left empty: an exception must not leave the OpenMP region; the cell reports it.
    }
  }
  return faces;
}

ElementHarmonicBasis cell_harmonic_basis(const PolyhedralMesh& mesh, int cell,
                                         const std::vector<std::optional<FaceHarmonicCoordinates>>& faces,
                                         const MfsOptions& options) {
  const Polyhedron polyhedron = cell_polyhedron(mesh, cell);
  const std::vector<int>& cell_faces = mesh.cell_faces[cell];
  std::vector<ElementFace> element_faces(cell_faces.size());
  for (size_t f = 0; f < cell_faces.size(); ++f) {
    const int face = cell_faces[f];
    if (!faces[face])
      throw std::invalid_argument("cell_harmonic_basis: face " + std::to_string(face) + " has no coordinates");
    // cell_polyhedron numbers the cell's nodes and keeps the stored loop, reversed for
    // the face's second cell: undo the reversal to match the coordinates' columns.
    element_faces[f].coordinates = &*faces[face];
    element_faces[f].nodes = polyhedron.faces[f];
    if (mesh.face_cells(face, 0) != cell) std::reverse(element_faces[f].nodes.begin(), element_faces[f].nodes.end());
  }
  return ElementHarmonicBasis(polyhedron, element_faces, options);
}

}  // namespace altfem::harmonic
