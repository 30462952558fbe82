#include "shared/mesh/structured_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "shared/mesh/elevate_order.hpp"

namespace altfem {

namespace {

VolumeMesh linear_grid(const AxisPlanes& coordinates, bool tetrahedra) {
  VolumeMesh mesh;
  Eigen::Vector3i n;
  for (int axis = 0; axis < 3; ++axis) n[axis] = static_cast<int>(coordinates[axis].size()) - 1;
  const auto index = [&](int i, int j, int k) { return i + (n.x() + 1) * (j + (n.y() + 1) * k); };
  mesh.nodes.resize(static_cast<Eigen::Index>(n.x() + 1) * (n.y() + 1) * (n.z() + 1), 3);
  for (int k = 0; k <= n.z(); ++k)
    for (int j = 0; j <= n.y(); ++j)
      for (int i = 0; i <= n.x(); ++i)
        mesh.nodes.row(index(i, j, k)) << coordinates[0][i], coordinates[1][j], coordinates[2][k];

  const int cubes = n.x() * n.y() * n.z();
  mesh.element_type = tetrahedra ? ElementType::tet4 : ElementType::hex8;
  mesh.cells.resize(tetrahedra ? 6 * cubes : cubes, tetrahedra ? 4 : 8);
  int cell = 0;
  for (int k = 0; k < n.z(); ++k)
    for (int j = 0; j < n.y(); ++j)
      for (int i = 0; i < n.x(); ++i) {
        // VTK hexahedron corner order.
        const std::array<int, 8> corner{
            index(i, j, k),     index(i + 1, j, k),     index(i + 1, j + 1, k),     index(i, j + 1, k),
            index(i, j, k + 1), index(i + 1, j, k + 1), index(i + 1, j + 1, k + 1), index(i, j + 1, k + 1)};
        if (!tetrahedra) {
          for (int c = 0; c < 8; ++c) mesh.cells(cell, c) = corner[c];
          ++cell;
          continue;
        }
        // Kuhn: for each ordering (a, b, c) of the axes, the path 0 → +e_a → +e_b → +e_c
        // from corner (0,0,0) to (1,1,1). Corner bits: x = 1, y = 2, z = 4.
        constexpr std::array<std::array<int, 3>, 6> orders{
            {{1, 2, 4}, {1, 4, 2}, {2, 1, 4}, {2, 4, 1}, {4, 1, 2}, {4, 2, 1}}};
        constexpr std::array<int, 8> vtk_of_bits{0, 1, 3, 2, 4, 5, 7, 6};
        for (const auto& order : orders) {
          std::array<int, 4> tet{};
          int bits = 0;
          tet[0] = corner[vtk_of_bits[0]];
          for (int s = 0; s < 3; ++s) {
            bits |= order[s];
            tet[s + 1] = corner[vtk_of_bits[bits]];
          }
          // Odd orderings of the axes give negatively oriented paths: swap to keep
          // every tetrahedron positive (VTK: (p1−p0)×(p2−p0)·(p3−p0) > 0).
          const Eigen::Vector3d p0 = mesh.nodes.row(tet[0]), p1 = mesh.nodes.row(tet[1]), p2 = mesh.nodes.row(tet[2]),
                                p3 = mesh.nodes.row(tet[3]);
          if ((p1 - p0).cross(p2 - p0).dot(p3 - p0) < 0) std::swap(tet[1], tet[2]);
          for (int c = 0; c < 4; ++c) mesh.cells(cell, c) = tet[c];
          ++cell;
        }
      }
  return mesh;
}

}  // namespace

VolumeMesh structured_grid(const Eigen::AlignedBox3d& box, const Eigen::Vector3i& resolution, ElementType type) {
  if ((resolution.array() < 1).any()) throw std::invalid_argument("structured_grid: resolution must be >= 1");
  if (!((box.sizes().array() > 0).all())) throw std::invalid_argument("structured_grid: the box is empty");
  AxisPlanes coordinates;
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i <= resolution[axis]; ++i)
      coordinates[axis].push_back(box.min()[axis] + box.sizes()[axis] * i / resolution[axis]);
  return rectilinear_grid(coordinates, type);
}

VolumeMesh rectilinear_grid(const AxisPlanes& coordinates, ElementType type) {
  for (const auto& axis : coordinates)
    if (axis.size() < 2 || !std::is_sorted(axis.begin(), axis.end(), std::less_equal<>()))
      throw std::invalid_argument("rectilinear_grid: every axis needs at least 2 strictly increasing coordinates");
  const bool tetrahedra = element_shape(type) == ElementShape::tetrahedron;
  return elevate_order(linear_grid(coordinates, tetrahedra), type);
}

Eigen::Vector3i default_grid_resolution(const Eigen::Vector3d& extent) {
  const double cell = std::min(extent.minCoeff() / 2.0, extent.maxCoeff() / 4.0);
  Eigen::Vector3i resolution;
  for (int i = 0; i < 3; ++i) {
    const double cells = extent[i] / cell;  // NaN or inf only for absurd (overflowing) boxes
    resolution[i] = !(cells >= 1.0) ? 1 : cells > 32.0 ? 32 : static_cast<int>(std::lround(cells));
  }
  return resolution;
}

}  // namespace altfem
