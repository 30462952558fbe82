#include "shared/mesh/polyhedral_mesh.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "shared/common/error.hpp"
#include "shared/geometry/monomial_index.hpp"
#include "shared/geometry/polygon_moments.hpp"
#include "shared/geometry/polyhedron_moments.hpp"

namespace altfem {

namespace {

Eigen::MatrixXd face_polygon(const PolyhedralMesh& mesh, int face) {
  const auto& loop = mesh.faces[face];
  Eigen::MatrixXd polygon(loop.size(), 3);
  for (std::size_t i = 0; i < loop.size(); ++i) polygon.row(i) = mesh.nodes.row(loop[i]);
  return polygon;
}

}  // namespace

Polyhedron cell_polyhedron(const PolyhedralMesh& mesh, int cell) {
  std::unordered_map<int, int> local_of_node;
  std::vector<int> nodes;
  Polyhedron polyhedron;
  for (int face : mesh.cell_faces[cell]) {
    std::vector<int> loop;
    loop.reserve(mesh.faces[face].size());
    for (int node : mesh.faces[face]) {
      auto [it, inserted] = local_of_node.emplace(node, static_cast<int>(nodes.size()));
      if (inserted) nodes.push_back(node);
      loop.push_back(it->second);
    }
    // The stored loop is outward for face_cells(f, 0); the other cell sees it reversed.
    if (mesh.face_cells(face, 0) != cell) std::reverse(loop.begin(), loop.end());
    polyhedron.faces.push_back(std::move(loop));
  }
  polyhedron.vertices.resize(static_cast<Eigen::Index>(nodes.size()), 3);
  for (std::size_t i = 0; i < nodes.size(); ++i) polyhedron.vertices.row(i) = mesh.nodes.row(nodes[i]);
  return polyhedron;
}

void compute_polyhedral_geometry(PolyhedralMesh& mesh) {
  const int face_count = mesh.face_count();
  // Checked here, not inside the parallel loops: an exception must not leave an OpenMP region.
  if (mesh.face_cells.rows() != face_count || mesh.face_cells.cols() != 2)
    throw std::invalid_argument("polyhedral mesh: face_cells must be #faces x 2");
  for (int face = 0; face < face_count; ++face) {
    if (mesh.faces[face].size() < 3)
      throw std::invalid_argument("polyhedral mesh: face " + std::to_string(face) + " has fewer than 3 nodes");
    for (int node : mesh.faces[face])
      if (node < 0 || node >= mesh.nodes.rows())
        throw std::invalid_argument("polyhedral mesh: face " + std::to_string(face) + " has a node out of range");
  }
  mesh.face_areas.resize(face_count);
  mesh.face_normals.resize(face_count, 3);
  mesh.face_centroids.resize(face_count, 3);
  const int x = monomial_index(1, 0, 0), y = monomial_index(0, 1, 0), z = monomial_index(0, 0, 1);
#pragma omp parallel for schedule(static)
  for (int face = 0; face < face_count; ++face) {
    const Eigen::MatrixXd polygon = face_polygon(mesh, face);
    const Eigen::Vector3d area_vector = polygon_area_vector(polygon);
    const double area = area_vector.norm();
    mesh.face_areas(face) = area;
    mesh.face_normals.row(face) = area > 0 ? Eigen::Vector3d(area_vector / area) : Eigen::Vector3d::Zero();
    mesh.face_centroids.row(face) = polygon.colwise().mean();
    // A face of no area (its nodes coincide to rounding: a cut's sliver, merged next) has
    // no moments; its centroid is its nodes' mean.
    if (!(area > 0)) continue;
    try {
      const Eigen::VectorXd moments = planar_polygon_moments(polygon, 1);
      if (moments(0) > 0)
        mesh.face_centroids.row(face) = Eigen::Vector3d(moments(x), moments(y), moments(z)) / moments(0);
    } catch (const std::invalid_argument&) {
    }
  }

  const int cell_count = mesh.cell_count();
  mesh.cell_volumes.resize(cell_count);
  mesh.cell_centroids.resize(cell_count, 3);
  mesh.cell_diameters.resize(cell_count);
  int bad_cell = -1;
#pragma omp parallel for schedule(dynamic, 64)
  for (int cell = 0; cell < cell_count; ++cell) {
    const Polyhedron polyhedron = cell_polyhedron(mesh, cell);
    Eigen::VectorXd moments;
    try {
      moments = polyhedron_moments(polyhedron, 1);
    } catch (const std::invalid_argument&) {
      moments = Eigen::VectorXd::Zero(1);  // its nodes coincide: no volume, reported below
    }
    const double volume = moments(0);
    if (!(volume > 0)) {
#pragma omp critical(altfem_polyhedral_bad_cell)
      if (bad_cell < 0 || cell < bad_cell) bad_cell = cell;
      continue;
    }
    mesh.cell_volumes(cell) = volume;
    mesh.cell_centroids.row(cell) = Eigen::Vector3d(moments(x), moments(y), moments(z)) / volume;
    double diameter = 0;
    const auto& vertices = polyhedron.vertices;
    for (Eigen::Index i = 0; i < vertices.rows(); ++i)
      for (Eigen::Index j = i + 1; j < vertices.rows(); ++j)
        diameter = std::max(diameter, (vertices.row(i) - vertices.row(j)).norm());
    mesh.cell_diameters(cell) = diameter;
  }
  if (bad_cell >= 0)
    throw NumericalError("polyhedral mesh: cell " + std::to_string(bad_cell) +
                         " has a non-positive volume (inverted or open faces)");
}

Eigen::Vector3d face_area_vector(const PolyhedralMesh& mesh, const std::vector<int>& loop) {
  Eigen::MatrixXd polygon(static_cast<Eigen::Index>(loop.size()), 3);
  for (std::size_t k = 0; k < loop.size(); ++k)
    polygon.row(static_cast<Eigen::Index>(k)) = mesh.nodes.row(loop[k]) - mesh.nodes.row(loop[0]);
  return polygon_area_vector(polygon);
}

void set_faces(PolyhedralMesh& mesh, std::vector<std::vector<int>> loops,
               const std::vector<std::array<int, 2>>& cells) {
  mesh.faces = std::move(loops);
  mesh.face_cells.resize(static_cast<Eigen::Index>(cells.size()), 2);
  for (auto& list : mesh.cell_faces) list.clear();
  for (std::size_t face = 0; face < cells.size(); ++face) {
    mesh.face_cells.row(static_cast<Eigen::Index>(face)) << cells[face][0], cells[face][1];
    for (const int cell : cells[face])
      if (cell >= 0) mesh.cell_faces[cell].push_back(static_cast<int>(face));
  }
}

PolyhedralMesh polyhedral_mesh_with_cells(const PolyhedralMesh& mesh, const std::vector<bool>& keep,
                                          std::vector<int>& kept, std::vector<int>* kept_faces) {
  std::vector<int> new_index(keep.size(), -1);
  for (std::size_t cell = 0; cell < keep.size(); ++cell)
    if (keep[cell]) {
      new_index[cell] = static_cast<int>(kept.size());
      kept.push_back(static_cast<int>(cell));
    }
  PolyhedralMesh result;
  result.nodes = mesh.nodes;
  result.cell_faces.resize(kept.size());
  for (const int cell : kept) result.cell_kinds.push_back(mesh.cell_kinds[cell]);
  std::vector<std::array<int, 2>> face_cells;
  for (int face = 0; face < mesh.face_count(); ++face) {
    const int first = mesh.face_cells(face, 0), second = mesh.face_cells(face, 1);
    const int kept_first = first >= 0 ? new_index[first] : -1, kept_second = second >= 0 ? new_index[second] : -1;
    if (kept_first < 0 && kept_second < 0) continue;
    std::vector<int> loop = mesh.faces[face];
    if (kept_first < 0) std::reverse(loop.begin(), loop.end());  // now oriented for the second
    const int index = static_cast<int>(result.faces.size());
    result.faces.push_back(std::move(loop));
    if (kept_faces) kept_faces->push_back(face);
    face_cells.push_back(kept_first >= 0 ? std::array<int, 2>{kept_first, kept_second}
                                         : std::array<int, 2>{kept_second, -1});
    for (const int cell : {kept_first, kept_second})
      if (cell >= 0) result.cell_faces[cell].push_back(index);
  }
  result.face_cells.resize(static_cast<Eigen::Index>(face_cells.size()), 2);
  for (std::size_t face = 0; face < face_cells.size(); ++face)
    result.face_cells.row(static_cast<Eigen::Index>(face)) << face_cells[face][0], face_cells[face][1];
  return result;
}

}  // namespace altfem
