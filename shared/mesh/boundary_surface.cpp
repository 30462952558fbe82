#include "shared/mesh/boundary_surface.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <span>

namespace altfem {

namespace {

// Outward faces of the VTK corner orderings (counter-clockwise seen from outside).
constexpr std::array<std::array<int, 4>, 4> tetrahedron_faces{{{0, 2, 1, -1}, {0, 1, 3, -1}, {1, 2, 3, -1}, {0, 3, 2, -1}}};
constexpr std::array<std::array<int, 4>, 6> hexahedron_faces{
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};

}  // namespace

BoundarySurface boundary_surface(const VolumeMesh& mesh) {
  const bool tetrahedra = element_shape(mesh.element_type) == ElementShape::tetrahedron;
  const std::span<const std::array<int, 4>> faces =
      tetrahedra ? std::span<const std::array<int, 4>>(tetrahedron_faces) : std::span<const std::array<int, 4>>(hexahedron_faces);
  const int corners = tetrahedra ? 3 : 4;

  // Count each face by its sorted corners; remember one (cell, face) for it.
  std::map<std::array<int, 4>, std::pair<int, int>> owner;
  std::map<std::array<int, 4>, int> count;
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
      std::array<int, 4> key{-1, -1, -1, -1};
      for (int c = 0; c < corners; ++c) key[c] = mesh.cells(cell, faces[f][c]);
      std::sort(key.begin(), key.begin() + corners);
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
