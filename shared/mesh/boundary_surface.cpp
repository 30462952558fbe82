#include "shared/mesh/boundary_surface.hpp"

#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include "shared/element/element_faces.hpp"
#include "shared/mesh/face_neighbours.hpp"

namespace altfem {

BoundarySurface boundary_surface(const VolumeMesh& mesh) {
  const ElementShape shape = element_shape(mesh.element_type);
  const std::span<const std::array<int, 4>> faces = element_faces(shape);
  const int corners = face_corner_count(shape);

  // A boundary face is one without a cell across it, in cell order.
  const std::vector<FaceNeighbour> neighbours = face_neighbours(mesh);

  BoundarySurface boundary;
  std::vector<int> vertex_of_node(static_cast<size_t>(mesh.nodes.rows()), -1);
  std::vector<std::array<int, 3>> triangles;
  const auto vertex = [&](int node) {
    if (vertex_of_node[node] < 0) {
      vertex_of_node[node] = static_cast<int>(boundary.mesh_nodes.size());
      boundary.mesh_nodes.push_back(node);
    }
    return vertex_of_node[node];
  };
  for (int cell = 0; cell < static_cast<int>(mesh.cells.rows()); ++cell)
    for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
      if (neighbours[static_cast<std::size_t>(cell) * faces.size() + f].cell >= 0) continue;
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
