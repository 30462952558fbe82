#include "shared/simulation/cell_stresses.hpp"

#include <Eigen/Eigenvalues>
#include <stdexcept>

namespace altfem {

std::vector<Eigen::Matrix3d> mean_cell_stresses(const TabulatedElements& elements,
                                                const std::vector<const Material*>& materials,
                                                const Eigen::VectorXd& u) {
  std::vector<LameParameters> lame;
  for (const Material* material : materials) lame.push_back(material->lame());
  std::vector<Eigen::Matrix3d> stresses(static_cast<std::size_t>(elements.size()));
#pragma omp parallel for schedule(dynamic, 16)
  for (int element = 0; element < elements.size(); ++element) {
    if (!elements.holds(element)) {  // another rank's: its sum below
      stresses[element].setZero();
      continue;
    }
    const ElementView view = elements[element];
    // ∫ ∇u dV: (∂u_i/∂x_j) = Σ_a u_a ⊗ ∇N_a, weighted.
    Eigen::Matrix<double, 3, Eigen::Dynamic> coefficients(3, view.basis_count());
    for (int a = 0; a < view.basis_count(); ++a) coefficients.col(a) = u.segment<3>(3 * Eigen::Index{view.basis[a]});
    Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();
    double volume = 0;
    for (int q = 0; q < view.point_count(); ++q) {
      gradient.noalias() += view.weights[q] * coefficients * view.gradients_at(q);
      volume += view.weights[q];
    }
    const Eigen::Matrix3d strain = 0.5 * (gradient + gradient.transpose()) / volume;
    const LameParameters& own = lame.at(view.material);
    stresses[element] = own.lambda * strain.trace() * Eigen::Matrix3d::Identity() + 2 * own.mu * strain;
  }
  static_assert(sizeof(Eigen::Matrix3d) == 9 * sizeof(double));
  elements.sum_over_ranks(std::span<double>(reinterpret_cast<double*>(stresses.data()), 9 * stresses.size()));
  return stresses;
}

PrincipalStress largest_principal_stress(const Eigen::Matrix3d& stress) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(stress);
  Eigen::Index largest = 0;
  solver.eigenvalues().cwiseAbs().maxCoeff(&largest);
  return {std::abs(solver.eigenvalues()[largest]), solver.eigenvectors().col(largest)};
}

}  // namespace altfem
