#pragma once
// A test fixture: the cells and faces of an n × n × n grid of [0,1]³ as DG sees them
// (each cell a polyhedron, every interior face once with its two cells, every boundary
// face with its outward normal), so the DG numerics can be verified before the
// polyhedral meshes of shared/mesh feed them.
#include "dg/dg_linear_system.hpp"

namespace altfem::test {

struct GridCells {
  std::vector<Polyhedron> cells;
  std::vector<dg::DgFace> faces;
};

inline GridCells hex_grid_cells(int n) {
  GridCells grid;
  const double h = 1.0 / n;
  const auto index = [n](int i, int j, int k) { return i + n * (j + n * k); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        Polyhedron cell;
        cell.vertices.resize(8, 3);
        for (int v = 0; v < 8; ++v)
          cell.vertices.row(v) << h * (i + (v & 1)), h * (j + ((v >> 1) & 1)), h * (k + ((v >> 2) & 1));
        cell.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        // The faces x = max, y = max, z = max of this cell (shared with the next cell or on
        // the boundary), and x/y/z = min on the boundary.
        const int here = index(i, j, k);
        const int axis_faces[3][2] = {{4, 5}, {2, 3}, {0, 1}};  // (min, max) face of each axis
        const int position[3] = {i, j, k};
        for (int axis = 0; axis < 3; ++axis)
          for (int side = 0; side < 2; ++side) {
            const bool boundary = side == 0 ? position[axis] == 0 : position[axis] == n - 1;
            if (side == 0 && !boundary) continue;  // counted from the neighbour below
            dg::DgFace face;
            const auto& loop = cell.faces[axis_faces[axis][side]];
            face.polygon.resize(4, 3);
            for (int v = 0; v < 4; ++v) face.polygon.row(v) = cell.vertices.row(loop[v]);
            face.normal = (side == 0 ? -1.0 : 1.0) * Eigen::Vector3d::Unit(axis);
            face.minus = here;
            if (!boundary) {
              int next[3] = {i, j, k};
              ++next[axis];
              face.plus = index(next[0], next[1], next[2]);
            }
            face.condition = boundary ? 0 : -1;
            grid.faces.push_back(face);
          }
        grid.cells.push_back(cell);
      }
  return grid;
}

}  // namespace altfem::test
