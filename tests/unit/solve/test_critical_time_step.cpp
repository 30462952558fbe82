// The explicit stability estimate (power iteration on M_e⁻¹K at rest) against a dense
// eigensolver on a spring chain fixed at node 0, whose stiffness and masses are known.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "shared/common/eigen_decompositions.hpp"
#include "shared/solve/critical_time_step.hpp"

namespace altfem {
namespace {

// n nodes on a line, one DOF each, springs between neighbours, uneven masses.
class SpringChain final : public Discretization {
public:
  explicit SpringChain(int nodes) : mass_(masses(nodes)), constrained_{0} {
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i + 1 < nodes; ++i) {
      const double k = 100.0 * (1.0 + 0.3 * std::cos(3.0 * i));
      entries.insert(entries.end(), {{i, i, k}, {i + 1, i + 1, k}, {i, i + 1, -k}, {i + 1, i, -k}});
    }
    stiffness_.resize(nodes, nodes);
    stiffness_.setFromTriplets(entries.begin(), entries.end());
    mass_matrix_ = Eigen::SparseMatrix<double>(mass_.diagonal().asDiagonal());
  }
  int dof_count() const override { return static_cast<int>(stiffness_.rows()); }
  double energy(const Eigen::VectorXd& u) const override { return 0.5 * u.dot(stiffness_ * u); }
  void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const override { gradient = stiffness_ * u; }
  void hessian(const Eigen::VectorXd&, Eigen::SparseMatrix<double>& hessian, bool) const override {
    hessian = stiffness_;
  }
  const Eigen::SparseMatrix<double>& hessian_pattern() const override { return stiffness_; }
  bool hessian_is_constant() const override { return true; }
  const Eigen::SparseMatrix<double>& mass_matrix() const override { return mass_matrix_; }
  const ExplicitMass& explicit_mass() const override { return mass_; }
  Eigen::VectorXd body_force(const Eigen::Vector3d&) const override { return Eigen::VectorXd::Zero(dof_count()); }
  const std::vector<int>& constrained_dofs() const override { return constrained_; }
  Eigen::VectorXd prescribed_displacement(double) const override { return Eigen::VectorXd::Zero(1); }

  /// 2 / ω_max with ω²_max the largest eigenvalue of M⁻¹K on the free DOFs, dense.
  double exact_critical_time_step() const {
    const Eigen::Index n = dof_count() - 1;
    const Eigen::VectorXd scale = mass_.diagonal().tail(n).cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd reduced =
        scale.asDiagonal() * Eigen::MatrixXd(stiffness_).bottomRightCorner(n, n) * scale.asDiagonal();
    return 2.0 / std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(reduced).eigenvalues().maxCoeff());
  }

private:
  static Eigen::VectorXd masses(int nodes) {
    Eigen::VectorXd values(nodes);
    for (int i = 0; i < nodes; ++i) values[i] = 1.0 + 0.5 * std::sin(i);
    return values;
  }

  Eigen::SparseMatrix<double> stiffness_, mass_matrix_;
  DiagonalMass mass_;
  std::vector<int> constrained_;
};

TEST(CriticalTimeStep, MatchesTheDenseEigenvalueFromAbove) {
  const SpringChain chain(12);
  const double exact = chain.exact_critical_time_step();
  const double estimate = estimate_critical_time_step(chain, 400);
  EXPECT_GE(estimate, exact * (1 - 1e-12));  // Rayleigh quotients approach ω²_max from below
  EXPECT_LT(estimate, 1.01 * exact);
}

}  // namespace
}  // namespace altfem
