#include "shared/mesh/polyhedral_from_volume_mesh.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <span>

namespace altfem {

namespace {

// Faces of a positively oriented cell in VTK corner numbering, counter-clockwise seen
// from outside (right-hand normal outward).
constexpr std::array<std::array<int, 3>, 4> tetrahedron_faces{{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
constexpr std::array<std::array<int, 4>, 6> hexahedron_faces{
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};

}  // namespace

PolyhedralMesh polyhedral_mesh_from_volume_mesh(const VolumeMesh& volume_mesh) {
  const ElementShape shape = element_shape(volume_mesh.element_type);
  const int corner_count = element_corner_count(volume_mesh.element_type);
  const int cell_count = static_cast<int>(volume_mesh.cells.rows());

  // Renumber the corner nodes in their original order; mid-edge/face/body nodes go.
  std::vector<int> new_index(volume_mesh.nodes.rows(), -1);
  for (int cell = 0; cell < cell_count; ++cell)
    for (int corner = 0; corner < corner_count; ++corner) new_index[volume_mesh.cells(cell, corner)] = 0;
  int node_count = 0;
  for (int& index : new_index)
    if (index == 0) index = node_count++;

  PolyhedralMesh mesh;
  mesh.nodes.resize(node_count, 3);
  for (std::size_t node = 0; node < new_index.size(); ++node)
    if (new_index[node] >= 0) mesh.nodes.row(new_index[node]) = volume_mesh.nodes.row(node);

  const int faces_per_cell = shape == ElementShape::tetrahedron ? 4 : 6;
  mesh.cell_faces.assign(cell_count, {});
  mesh.cell_kinds.assign(cell_count, shape == ElementShape::tetrahedron ? PolyhedralCellKind::tetrahedron
                                                                        : PolyhedralCellKind::hexahedron);
  std::vector<std::array<int, 2>> face_cells;
  // A face is identified by its sorted node set; the second cell to see it joins it.
  std::map<std::vector<int>, int> face_of_nodes;
  auto add_face = [&](int cell, std::span<const int> corners) {
    std::vector<int> loop;
    for (int corner : corners) loop.push_back(new_index[volume_mesh.cells(cell, corner)]);
    std::vector<int> key = loop;
    std::sort(key.begin(), key.end());
    auto [it, inserted] = face_of_nodes.emplace(std::move(key), static_cast<int>(mesh.faces.size()));
    if (inserted) {
      mesh.faces.push_back(std::move(loop));
      face_cells.push_back({cell, -1});
    } else {
      face_cells[it->second][1] = cell;
    }
    mesh.cell_faces[cell].push_back(it->second);
  };
  for (int cell = 0; cell < cell_count; ++cell) {
    mesh.cell_faces[cell].reserve(faces_per_cell);
    if (shape == ElementShape::tetrahedron)
      for (const auto& face : tetrahedron_faces) add_face(cell, face);
    else
      for (const auto& face : hexahedron_faces) add_face(cell, face);
  }
  mesh.face_cells.resize(static_cast<Eigen::Index>(face_cells.size()), 2);
  for (std::size_t face = 0; face < face_cells.size(); ++face)
    mesh.face_cells.row(face) << face_cells[face][0], face_cells[face][1];
  compute_polyhedral_geometry(mesh);
  return mesh;
}

}  // namespace altfem
