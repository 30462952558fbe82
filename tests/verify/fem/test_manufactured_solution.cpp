// Convergence of linear elasticity on the unit cube to a manufactured solution.
//
// u_i(x) = α_i sin(k_i · x + φ_i) (no sum; one wave vector per component), so
//   ∂_j u_i = α_i k_ij cos(k_i · x + φ_i),  ∂_j ∂_l u_i = −α_i k_ij k_il sin(k_i · x + φ_i),
// and with σ = λ tr(ε) I + 2μ ε, div σ = μ Δu + (λ + μ) ∇(div u), the body force is
//   f_i = −(div σ)_i = μ α_i |k_i|² s_i + (λ + μ) Σ_j α_j k_ji k_jj s_j,   s_j = sin(k_j · x + φ_j).
// u is imposed at the boundary nodes, the load vector is ∫ f N_a (quadrature of the
// solve), and the L2 and H1-seminorm errors use a rule of higher strength. Rates are
// measured between the two finest meshes and must be p + 1 (L2) and p (H1) ± 0.2.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "shared/fem/tabulate_lagrange.hpp"
#include "tests/unit/fem/test_meshes.hpp"
#include "tests/unit/newton/loaded_potential.hpp"

namespace altfem {
namespace {

constexpr double youngs_modulus = 1.0, poisson_ratio = 0.3;

struct Manufactured {
  Eigen::Matrix3d k;  // row i: the wave vector of component i
  Eigen::Vector3d alpha{0.1, -0.08, 0.12}, phase{0.3, 1.1, -0.4};
  double lambda, mu;

  Manufactured() {
    k << 1.3, 0.7, 0.9, -0.6, 1.4, 0.5, 0.8, -0.4, 1.2;
    k *= 1.5;
    const LameParameters lame = lame_parameters(youngs_modulus, poisson_ratio);
    lambda = lame.lambda;
    mu = lame.mu;
  }
  Eigen::Vector3d sines(const Eigen::Vector3d& x) const { return (k * x + phase).array().sin(); }
  Eigen::Vector3d displacement(const Eigen::Vector3d& x) const { return alpha.cwiseProduct(sines(x)); }
  /// ∂u_i/∂x_j (3 × 3).
  Eigen::Matrix3d gradient(const Eigen::Vector3d& x) const {
    const Eigen::Vector3d cosines = (k * x + phase).array().cos();
    return alpha.cwiseProduct(cosines).asDiagonal() * k;
  }
  Eigen::Vector3d body_force(const Eigen::Vector3d& x) const {
    const Eigen::Vector3d s = sines(x);
    Eigen::Vector3d f;
    for (int i = 0; i < 3; ++i) {
      f[i] = mu * alpha[i] * k.row(i).squaredNorm() * s[i];
      for (int j = 0; j < 3; ++j) f[i] += (lambda + mu) * alpha[j] * k(j, i) * k(j, j) * s[j];
    }
    return f;
  }
};

/// x_q = Σ_a N_a(x_q) X_a: the isoparametric map (basis function a is mesh node a).
Eigen::Vector3d point_of(const ElementView& element, int q, const VolumeMesh& mesh) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int a = 0; a < element.basis_count(); ++a)
    x += element.values(q, a) * mesh.nodes.row(element.basis[a]).transpose();
  return x;
}

Eigen::VectorXd load_vector(const TabulatedElements& elements, const VolumeMesh& mesh, const Manufactured& exact) {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(3 * mesh.nodes.rows());
  for (int e = 0; e < elements.size(); ++e) {
    const ElementView element = elements[e];
    for (int q = 0; q < element.point_count(); ++q) {
      const Eigen::Vector3d f = element.weights[q] * exact.body_force(point_of(element, q, mesh));
      for (int a = 0; a < element.basis_count(); ++a) load.segment<3>(3 * element.basis[a]) += element.values(q, a) * f;
    }
  }
  return load;
}

struct Errors {
  double l2 = 0, h1 = 0;
};

Errors errors(const TabulatedElements& elements, const VolumeMesh& mesh, const Eigen::VectorXd& u,
              const Manufactured& exact) {
  Errors squared;
  for (int e = 0; e < elements.size(); ++e) {
    const ElementView element = elements[e];
    for (int q = 0; q < element.point_count(); ++q) {
      const Eigen::Vector3d x = point_of(element, q, mesh);
      Eigen::Vector3d value = Eigen::Vector3d::Zero();
      Eigen::Matrix3d gradient = Eigen::Matrix3d::Zero();
      const auto g = element.gradients_at(q);
      for (int a = 0; a < element.basis_count(); ++a) {
        const Eigen::Vector3d u_a = u.segment<3>(3 * element.basis[a]);
        value += element.values(q, a) * u_a;
        gradient += u_a * g.row(a);
      }
      squared.l2 += element.weights[q] * (value - exact.displacement(x)).squaredNorm();
      squared.h1 += element.weights[q] * (gradient - exact.gradient(x)).squaredNorm();
    }
  }
  return {std::sqrt(squared.l2), std::sqrt(squared.h1)};
}

struct Case {
  ElementType type;
  std::vector<int> resolutions;
};

class ManufacturedSolution : public ::testing::TestWithParam<Case> {};

TEST_P(ManufacturedSolution, OptimalL2AndH1Rates) {
  const auto start = std::chrono::steady_clock::now();
  const ElementType type = GetParam().type;
  const int p = element_degree(type);
  const Manufactured exact;
  const auto material = make_material(MaterialModel::linear, youngs_modulus, poisson_ratio, 1.0);
  std::vector<Errors> measured;
  for (int n : GetParam().resolutions) {
    const VolumeMesh mesh = structured_grid(test::unit_cube(), Eigen::Vector3i::Constant(n), type);
    const TabulatedElements elements = tabulate_lagrange(mesh, 2 * p + 2);
    const ElasticAssembler assembler(elements, {material.get()});
    const std::vector<int> constrained = test::boundary_dofs(mesh, test::unit_cube());
    const Eigen::VectorXd interpolant =
        test::nodal_values(mesh, [&](const Eigen::Vector3d& x) { return exact.displacement(x); });
    Eigen::VectorXd prescribed(static_cast<Eigen::Index>(constrained.size()));
    for (size_t i = 0; i < constrained.size(); ++i)
      prescribed[static_cast<Eigen::Index>(i)] = interpolant[constrained[i]];
    const Eigen::VectorXd u =
        test::solve_static(assembler, load_vector(elements, mesh, exact), constrained, prescribed);
    measured.push_back(errors(tabulate_lagrange(mesh, 2 * p + 6), mesh, u, exact));
    std::printf("[ mms      ] %s n=%d: %ld DOFs, L2 %.3e, H1 %.3e\n", std::string(element_name(type)).c_str(), n,
                static_cast<long>(u.size()), measured.back().l2, measured.back().h1);
  }
  const size_t last = measured.size() - 1;
  const double ratio = double(GetParam().resolutions[last]) / GetParam().resolutions[last - 1];
  const double l2_rate = std::log(measured[last - 1].l2 / measured[last].l2) / std::log(ratio);
  const double h1_rate = std::log(measured[last - 1].h1 / measured[last].h1) / std::log(ratio);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ mms      ] %s: L2 rate %.3f (expected %d), H1 rate %.3f (expected %d), %.1f s\n",
              std::string(element_name(type)).c_str(), l2_rate, p + 1, h1_rate, p, seconds);
  EXPECT_NEAR(l2_rate, p + 1, 0.2);
  EXPECT_NEAR(h1_rate, p, 0.2);
}

INSTANTIATE_TEST_SUITE_P(Fem, ManufacturedSolution,
                         ::testing::Values(Case{ElementType::tet4, {4, 8, 16}}, Case{ElementType::hex8, {4, 8, 16}},
                                           Case{ElementType::tet10, {2, 4, 8}}, Case{ElementType::hex20, {2, 4, 8}},
                                           Case{ElementType::hex27, {2, 4, 8}}, Case{ElementType::tet20, {2, 4, 6}}),
                         [](const auto& info) { return std::string(element_name(info.param.type)); });

}  // namespace
}  // namespace altfem
