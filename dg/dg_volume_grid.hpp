#pragma once
// dg's volume output (`volume.pvd`): each cell with its own copy of its vertices, each
// displaced by its own polynomial, so the frames show DG's discontinuities; cell data
// "element", the cell's index.
#include <Eigen/Core>

#include "dg/dg_linear_system.hpp"
#include "shared/io/unstructured_grid.hpp"

namespace altfem::dg {

/// The cells of `system` as VTK polyhedra with point data "displacement" (#points × 3)
/// from the coefficients u (#dofs).
UnstructuredGrid dg_volume_grid(const DgLinearSystem& system, const Eigen::VectorXd& u);

}  // namespace altfem::dg
