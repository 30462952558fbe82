#include "shared/mesh/boundary_surface.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <span>

#include "shared/element/element_faces.hpp"

namespace altfem {

BoundarySurface boundary_surface(const VolumeMesh& mesh) {
  const ElementShape shape = element_shape(mesh.element_type);
  const std::span<const std::array<int, 4>> faces = element_faces(shape);
  const int corners = face_corner_count(shape);

  // Count each face by its sorted corners; remember one (cell, face) for it.
  std::map<std::array<int, 4>, std::pair<int, int>> owner;
  std::map<std::array<int, 4>, int> count;
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
      std::array<int, 4> key{-1, -1, -1, -1};
      for (int c = 0; c < corners; ++c) key[c] = mesh.cells(cell, faces[f][c]);
      std::sort(key.begin(), key.end());  // a triangle's -1 pad sorts first
      ++count[key];
      owner[key] = {static_cast<int>(cell), f};
    }

  BoundarySurface boundary;
  std::map<int, int> vertex_of_node;
  std::vector<std::array<int, 3>> triangles;
  const auto vertex = [&](int node) {
    auto [entry, inserted] = vertex_of_node.try_emplace(node, static_cast<int>(boundary.mesh_nodes.size()));
    if (inserted) boundary.mesh_nodes.push_back(node);
    return entry->second;
  };
  for (const auto& [key, number] : count) {
    if (number != 1) continue;
    const auto [cell, f] = owner[key];
    std::array<int, 4> face{};
    for (int c = 0; c < corners; ++c) face[c] = vertex(mesh.cells(cell, faces[f][c]));
    triangles.push_back({face[0], face[1], face[2]});
    boundary.cells.push_back(cell);
    if (corners == 4) {
      triangles.push_back({face[0], face[2], face[3]});
      boundary.cells.push_back(cell);
    }
  }
  boundary.surface.vertices.resize(static_cast<Eigen::Index>(boundary.mesh_nodes.size()), 3);
  for (size_t i = 0; i < boundary.mesh_nodes.size(); ++i)
    boundary.surface.vertices.row(static_cast<Eigen::Index>(i)) = mesh.nodes.row(boundary.mesh_nodes[i]);
  boundary.surface.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (size_t t = 0; t < triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) boundary.surface.triangles(static_cast<Eigen::Index>(t), c) = triangles[t][c];
  return boundary;
}

}  // namespace altfem
