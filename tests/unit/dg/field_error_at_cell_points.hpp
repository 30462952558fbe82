#pragma once
// The largest |u_h(x) − field(x)| over every cell's vertices and centroid, u_h the DG field
// of `coefficients` (#dofs) in `system`'s bases on `mesh`'s cells: whether a coarse space
// or an interpolation reproduces a polynomial field cell by cell.
#include <Eigen/Core>
#include <algorithm>

#include "dg/dg_linear_system.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem::dg {

template <typename Field>
double field_error_at_cell_points(const PolyhedralMesh& mesh, const DgLinearSystem& system,
                                  const Eigen::VectorXd& coefficients, const Field& field) {
  double error = 0;
  Eigen::VectorXd values;
  Eigen::MatrixXd gradients;
  for (int cell = 0; cell < system.cell_count(); ++cell) {
    const Polyhedron& polyhedron = system.cell(cell);
    Eigen::MatrixXd points(polyhedron.vertices.rows() + 1, 3);
    points << polyhedron.vertices, mesh.cell_centroids.row(cell);
    for (Eigen::Index p = 0; p < points.rows(); ++p) {
      const Eigen::Vector3d x = points.row(p);
      system.basis(cell).evaluate(x, values, gradients);
      Eigen::Vector3d u = Eigen::Vector3d::Zero();
      for (Eigen::Index a = 0; a < values.size(); ++a)
        u += values[a] * coefficients.segment<3>(3 * (system.offset(cell) + a));
      error = std::max(error, (u - field(x)).norm());
    }
  }
  return error;
}

}  // namespace altfem::dg
