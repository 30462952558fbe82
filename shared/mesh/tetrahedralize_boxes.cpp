// Exact Tet4 meshes of shapes built from axis-aligned boxes (tetrahedralize.hpp).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shared/common/error.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/mesh/tetrahedralize.hpp"
#include "shared/mesh/volume_mesh_cells.hpp"

namespace altfem {

namespace {

// Every interval between consecutive planes split into equal cells of at most `size`:
// the planes stay grid planes, so each grid cell lies wholly inside or outside.
AxisPlanes refined(const AxisPlanes& planes, double size) {
  AxisPlanes coordinates;
  for (int axis = 0; axis < 3; ++axis) {
    const std::vector<double>& own = planes[axis];
    coordinates[axis].push_back(own.front());
    for (std::size_t i = 0; i + 1 < own.size(); ++i) {
      const int cells = std::max(1, static_cast<int>(std::ceil((own[i + 1] - own[i]) / size - 1e-9)));
      for (int c = 1; c < cells; ++c) coordinates[axis].push_back(own[i] + (own[i + 1] - own[i]) * c / cells);
      coordinates[axis].push_back(own[i + 1]);
    }
  }
  return coordinates;
}

}  // namespace

VolumeMesh tetrahedralize_box_shape(const AnalyticShape& shape, double max_cell_size) {
  const std::optional<AxisPlanes> planes = shape.axis_planes();
  if (!planes) throw std::invalid_argument("tetrahedralize_box_shape: the shape has a curved part");
  if (!(max_cell_size > 0)) throw InputError("tetrahedralize: max_cell_size must be > 0");
  // max_cell_size bounds circumradii, as Mesh_3's cell_size does: a Kuhn tetrahedron's
  // circumradius is half its cube's diagonal, so cubes of side 2 / √3 · max_cell_size.
  const double side = 2.0 / std::sqrt(3.0) * max_cell_size;
  const VolumeMesh grid = rectilinear_grid(refined(*planes, side), ElementType::tet4);

  // A Kuhn tetrahedron's centroid lies inside its grid cell, which the shape holds
  // wholly or not at all.
  std::vector<int> kept_cells;
  for (Eigen::Index cell = 0; cell < grid.cells.rows(); ++cell) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int corner = 0; corner < 4; ++corner) centroid += grid.nodes.row(grid.cells(cell, corner)).transpose() / 4.0;
    if (shape.level_set(centroid) < 0) kept_cells.push_back(static_cast<int>(cell));
  }
  if (kept_cells.empty()) throw InputError("tetrahedralize: the shape holds no grid cell");

  return volume_mesh_cells(grid, kept_cells);
}

}  // namespace altfem
