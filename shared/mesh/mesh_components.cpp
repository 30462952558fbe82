#include "shared/mesh/mesh_components.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>

#include "shared/element/element_faces.hpp"
#include "shared/mesh/disjoint_sets.hpp"
#include "shared/mesh/face_neighbours.hpp"

namespace altfem {

namespace {

int count_roots(DisjointSets& sets, int count, const std::vector<char>& member) {
  std::set<int> roots;
  for (int i = 0; i < count; ++i)
    if (member.empty() || member[i]) roots.insert(sets.find(i));
  return static_cast<int>(roots.size());
}

}  // namespace

int volume_mesh_components(const VolumeMesh& mesh) {
  const int cells = static_cast<int>(mesh.cells.rows());
  DisjointSets sets(cells);
  const std::vector<FaceNeighbour> neighbours = face_neighbours(mesh);
  const std::size_t face_count = element_faces(element_shape(mesh.element_type)).size();
  for (std::size_t side = 0; side < neighbours.size(); ++side)
    if (neighbours[side].cell >= 0) sets.join(static_cast<int>(side / face_count), neighbours[side].cell);
  return count_roots(sets, cells, {});
}

int polyhedral_mesh_components(const PolyhedralMesh& mesh) {
  DisjointSets sets(mesh.cell_count());
  for (int face = 0; face < mesh.face_count(); ++face)
    if (!mesh.is_boundary_face(face)) sets.join(mesh.face_cells(face, 0), mesh.face_cells(face, 1));
  return count_roots(sets, mesh.cell_count(), {});
}

int surface_solid_components(const SurfaceMesh& surface) {
  const int triangles = static_cast<int>(surface.triangles.rows());
  DisjointSets sets(triangles);
  std::map<std::pair<int, int>, int> first_triangle_of_edge;
  for (int t = 0; t < triangles; ++t)
    for (int e = 0; e < 3; ++e) {
      const int a = surface.triangles(t, e), b = surface.triangles(t, (e + 1) % 3);
      const auto [entry, inserted] = first_triangle_of_edge.try_emplace({std::min(a, b), std::max(a, b)}, t);
      if (!inserted) sets.join(entry->second, t);
    }
  // Each shell's enclosed volume by the divergence theorem (surface_volume's sum).
  std::unordered_map<int, double> shell_volume;
  for (int t = 0; t < triangles; ++t) {
    const Eigen::Vector3d a = surface.vertices.row(surface.triangles(t, 0)),
                          b = surface.vertices.row(surface.triangles(t, 1)),
                          c = surface.vertices.row(surface.triangles(t, 2));
    shell_volume[sets.find(t)] += a.dot(b.cross(c)) / 6.0;
  }
  return static_cast<int>(
      std::count_if(shell_volume.begin(), shell_volume.end(), [](const auto& shell) { return shell.second > 0; }));
}

std::vector<int> surface_vertex_pieces(const SurfaceMesh& surface) {
  DisjointSets sets(static_cast<int>(surface.vertices.rows()));
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t)
    for (int k = 1; k < 3; ++k) {
      // The lower vertex stays the root, so each piece is numbered by its lowest vertex.
      const int a = sets.find(surface.triangles(t, 0)), b = sets.find(surface.triangles(t, k));
      sets.join(std::min(a, b), std::max(a, b));
    }
  std::vector<int> piece(static_cast<std::size_t>(surface.vertices.rows()));
  for (std::size_t v = 0; v < piece.size(); ++v) piece[v] = sets.find(static_cast<int>(v));
  return piece;
}

int shape_components(const AnalyticShape& shape, double spacing) {
  const Eigen::AlignedBox3d box = shape.bounding_box();
  Eigen::Vector3i n;
  for (int axis = 0; axis < 3; ++axis) n[axis] = std::max(1, static_cast<int>(std::ceil(box.sizes()[axis] / spacing)));
  const int count = n.prod();
  const auto index = [&](int i, int j, int k) { return i + n.x() * (j + n.y() * k); };
  std::vector<char> inside(static_cast<std::size_t>(count));
#pragma omp parallel for schedule(static)
  for (int k = 0; k < n.z(); ++k)
    for (int j = 0; j < n.y(); ++j)
      for (int i = 0; i < n.x(); ++i) {
        const Eigen::Vector3d centre =
            box.min() +
            box.sizes().cwiseProduct(Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5)).cwiseQuotient(n.cast<double>());
        inside[index(i, j, k)] = shape.level_set(centre) < 0;
      }
  DisjointSets sets(count);
  for (int k = 0; k < n.z(); ++k)
    for (int j = 0; j < n.y(); ++j)
      for (int i = 0; i < n.x(); ++i) {
        if (!inside[index(i, j, k)]) continue;
        if (i + 1 < n.x() && inside[index(i + 1, j, k)]) sets.join(index(i, j, k), index(i + 1, j, k));
        if (j + 1 < n.y() && inside[index(i, j + 1, k)]) sets.join(index(i, j, k), index(i, j + 1, k));
        if (k + 1 < n.z() && inside[index(i, j, k + 1)]) sets.join(index(i, j, k), index(i, j, k + 1));
      }
  return count_roots(sets, count, inside);
}

}  // namespace altfem
