#include "dg/monomial_basis_evaluator.hpp"

#include <limits>

#include "shared/mesh/polyhedral_cell_location.hpp"

namespace altfem::dg {

MonomialBasisEvaluator::MonomialBasisEvaluator(const PolyhedralMesh& mesh, const DgLinearSystem& system)
    : mesh_(mesh), system_(system), bounds_(mesh.cell_count()) {
  for (int cell = 0; cell < mesh.cell_count(); ++cell)
    for (int face : mesh.cell_faces[cell])
      for (int node : mesh.faces[face]) bounds_[cell].extend(mesh.nodes.row(node).transpose());
}

bool MonomialBasisEvaluator::evaluate_inside(int element, const Eigen::Vector3d& x, std::vector<int>& basis,
                                             std::vector<double>& values) const {
  const double tolerance = 1e-9 * mesh_.cell_diameters[element];
  if (bounds_[element].exteriorDistance(x) > tolerance || !cell_holds(mesh_, element, x, tolerance)) return false;
  fill(element, x, basis, values);
  return true;
}

double MonomialBasisEvaluator::evaluate_nearest(const Eigen::Vector3d& x, std::vector<int>& basis,
                                                std::vector<double>& values) const {
  int nearest = 0;
  double nearest_distance = std::numeric_limits<double>::infinity();
  for (int cell = 0; cell < mesh_.cell_count(); ++cell) {
    // The box's distance bounds the boundary's from below: it prunes.
    const double box_distance = bounds_[cell].exteriorDistance(x);
    if (box_distance >= nearest_distance) continue;
    const double distance = distance_to_cell_boundary(mesh_, cell, x);
    if (distance < nearest_distance) {
      nearest = cell;
      nearest_distance = distance;
    }
  }
  fill(nearest, x, basis, values);
  return std::max(nearest_distance, 0.0);
}

void MonomialBasisEvaluator::fill(int element, const Eigen::Vector3d& x, std::vector<int>& basis,
                                  std::vector<double>& values) const {
  Eigen::VectorXd phi;
  Eigen::MatrixXd gradients;
  system_.basis(element).evaluate(x, phi, gradients);
  const int count = static_cast<int>(phi.size()), first = system_.offset(element);
  basis.resize(count);
  values.resize(count);
  for (int a = 0; a < count; ++a) {
    basis[a] = first + a;
    values[a] = phi[a];
  }
}

}  // namespace altfem::dg
