#include "shared/mesh/boundary_surface.hpp"

#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include "shared/element/element_faces.hpp"

namespace altfem {

BoundarySurface boundary_surface(const VolumeMesh& mesh) {
  const ElementShape shape = element_shape(mesh.element_type);
  const std::span<const std::array<int, 4>> faces = element_faces(shape);
  const int corners = face_corner_count(shape);

  // Every face by its sorted corners, sorted: a boundary face is one no other face
  // repeats. (Two maps counting the faces were 4% of the fcm pencil's run under `perf`: it
  // takes the boundary of its embedded tetrahedra again after every cut.)
  struct Face {
    std::array<int, 4> key;
    int cell, face;
  };
  std::vector<Face> all;
  all.reserve(static_cast<size_t>(mesh.cells.rows()) * faces.size());
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
      std::array<int, 4> key{-1, -1, -1, -1};
      for (int c = 0; c < corners; ++c) key[c] = mesh.cells(cell, faces[f][c]);
      std::sort(key.begin(), key.end());  // a triangle's -1 pad sorts first
      all.push_back({key, static_cast<int>(cell), f});
    }
  std::sort(all.begin(), all.end(), [](const Face& a, const Face& b) { return a.key < b.key; });

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
  for (size_t first = 0, next = 0; first < all.size(); first = next) {
    for (next = first + 1; next < all.size() && all[next].key == all[first].key;) ++next;
    if (next - first != 1) continue;
    const int cell = all[first].cell, f = all[first].face;
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
