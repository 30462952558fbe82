#include <cmath>
#include <string>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/mesh/corner_tetrahedra.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

std::span<const std::array<int, 4>> corner_tetrahedra(ElementShape shape) {
  static constexpr std::array<std::array<int, 4>, 1> tetrahedron{{{0, 1, 2, 3}}};
  static constexpr std::array<std::array<int, 4>, 8> hexahedron{
      {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7}, {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}}};
  if (shape == ElementShape::tetrahedron) return tetrahedron;
  return hexahedron;
}

namespace {
[[noreturn]] void fail(const std::string& file_name, const std::string& what) {
  throw InputError(input_message(file_name, "", what));
}
}  // namespace

void check_volume_mesh(const VolumeMesh& mesh, const std::string& file_name) {
  const int per_cell = element_node_count(mesh.element_type);
  if (mesh.nodes.cols() != 3)
    fail(file_name, "nodes must have 3 coordinates, got " + std::to_string(mesh.nodes.cols()));
  if (mesh.cells.cols() != per_cell)
    fail(file_name, std::string(element_name(mesh.element_type)) + " cells need " + std::to_string(per_cell) +
                        " nodes, got " + std::to_string(mesh.cells.cols()));
  if (mesh.cells.rows() == 0) fail(file_name, "the mesh has no cells");
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node)
    if (!mesh.nodes.row(node).allFinite())
      fail(file_name, "node " + std::to_string(node) + " has a non-finite coordinate");

  std::vector<bool> used(mesh.nodes.rows(), false);
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (Eigen::Index i = 0; i < per_cell; ++i) {
      const int node = mesh.cells(cell, i);
      if (node < 0 || node >= mesh.nodes.rows())
        fail(file_name, "cell " + std::to_string(cell) + " refers to node " + std::to_string(node) +
                            ", expected 0 to " + std::to_string(mesh.nodes.rows() - 1));
      used[node] = true;
    }
  for (std::size_t node = 0; node < used.size(); ++node)
    if (!used[node]) fail(file_name, "node " + std::to_string(node) + " is not used by any cell");

  // A corner tetrahedron counts as flat when its volume is below a tiny fraction of
  // the product of its edge lengths (scale-free, so any unit system works).
  constexpr double flatness = 1e-10;
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (const auto& tet : corner_tetrahedra(element_shape(mesh.element_type))) {
      const Eigen::Vector3d a = mesh.nodes.row(mesh.cells(cell, tet[0]));
      const Eigen::Vector3d b = mesh.nodes.row(mesh.cells(cell, tet[1]));
      const Eigen::Vector3d c = mesh.nodes.row(mesh.cells(cell, tet[2]));
      const Eigen::Vector3d d = mesh.nodes.row(mesh.cells(cell, tet[3]));
      const double volume = six_signed_volume(a, b, c, d);
      const double scale = (b - a).norm() * (c - a).norm() * (d - a).norm();
      if (std::abs(volume) <= flatness * scale)
        fail(file_name,
             "cell " + std::to_string(cell) + " (0-based) has zero volume at its corner " + std::to_string(tet[0]));
      if (volume < 0)
        fail(file_name, "cell " + std::to_string(cell) + " (0-based) is inverted (negative volume at its corner " +
                            std::to_string(tet[0]) + ")");
    }
}

}  // namespace altfem
