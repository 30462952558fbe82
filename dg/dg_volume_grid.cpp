#include "dg/dg_volume_grid.hpp"

#include <cstdint>
#include <vector>

namespace altfem::dg {

UnstructuredGrid dg_volume_grid(const DgLinearSystem& system, const Eigen::VectorXd& u) {
  UnstructuredGrid grid;
  std::vector<Eigen::Vector3d> points, displacements;
  Eigen::MatrixXd elements(system.cell_count(), 1);
  Eigen::VectorXd phi;
  Eigen::MatrixXd gradients;
  std::vector<std::vector<int64_t>> faces;
  for (int cell = 0; cell < system.cell_count(); ++cell) {
    const Polyhedron polyhedron = system.cell(cell);
    const auto first = static_cast<int64_t>(points.size());
    for (Eigen::Index v = 0; v < polyhedron.vertices.rows(); ++v) {
      const Eigen::Vector3d x = polyhedron.vertices.row(v).transpose();
      system.basis(cell).evaluate(x, phi, gradients);
      Eigen::Vector3d value = Eigen::Vector3d::Zero();
      for (Eigen::Index a = 0; a < phi.size(); ++a) value += phi[a] * u.segment<3>(3 * (system.offset(cell) + a));
      points.push_back(x);
      displacements.push_back(value);
    }
    faces.clear();
    for (const auto& loop : polyhedron.faces) {
      faces.emplace_back();
      for (int v : loop) faces.back().push_back(first + v);
    }
    grid.add_polyhedron(faces);
    elements(cell, 0) = cell;
  }
  grid.points.resize(static_cast<Eigen::Index>(points.size()), 3);
  Eigen::MatrixXd displacement(grid.points.rows(), 3);
  for (size_t p = 0; p < points.size(); ++p) {
    grid.points.row(p) = points[p].transpose();
    displacement.row(p) = displacements[p].transpose();
  }
  grid.point_data.emplace_back("displacement", std::move(displacement));
  grid.cell_data.emplace_back("element", std::move(elements));
  return grid;
}

}  // namespace altfem::dg
