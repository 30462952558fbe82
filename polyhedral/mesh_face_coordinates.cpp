#include "polyhedral/mesh_face_coordinates.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "polyhedral/canonical_cell.hpp"

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
  // Chunks of four: an event's few new cells have a few dozen faces.
#pragma omp parallel for schedule(dynamic, 4)
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
  const CanonicalCell canonical = canonical_cell(mesh, cell);
  std::vector<ElementFace> element_faces(canonical.mesh_faces.size());
  for (size_t f = 0; f < canonical.mesh_faces.size(); ++f) {
    const int face = canonical.mesh_faces[f];
    if (!faces[face])
      throw std::invalid_argument("cell_harmonic_basis: face " + std::to_string(face) + " has no coordinates");
    // The coordinates' columns are the stored loop's nodes, which the cell numbers as
    // cell_nodes does.
    element_faces[f].coordinates = &*faces[face];
    for (int node : mesh.faces[face]) {
      const auto local = std::find(canonical.nodes.begin(), canonical.nodes.end(), node) - canonical.nodes.begin();
      element_faces[f].nodes.push_back(canonical.sorted[local]);
    }
  }
  // Fitted on the canonical cell (its nodes sorted), returned in cell_nodes order.
  return ElementHarmonicBasis(canonical.polyhedron, element_faces, options).reordered(canonical.sorted);
}

}  // namespace altfem::harmonic
