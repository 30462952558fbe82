// ElasticAssembler's dynamic kernel path (issue #14, item 7): hand-built elements of
// 4, 7, 10 and 13 basis functions with random traces, against a dense reference
// computed here and against finite differences; BlockSparsity with extra couplings
// holds exactly the element and group pairs, and its offsets point at them.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>
#include <utility>

#include "shared/assembly/elastic_assembler.hpp"
#include "shared/material/material.hpp"
#include "tests/unit/assembly/assembly_fixture.hpp"

namespace altfem {
namespace {

constexpr int pool_size = 24;

// 8 elements of 4, 7, 10 and 13 functions drawn from 24, random positive weights,
// random values and gradients.
TabulatedElements mixed_elements(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  TabulatedElements elements;
  for (int size : {4, 7, 10, 13, 13, 7, 4, 10}) {
    std::vector<int> basis(pool_size);
    std::iota(basis.begin(), basis.end(), 0);
    std::shuffle(basis.begin(), basis.end(), random);
    basis.resize(size);
    const int points = 3 + size % 4;
    std::vector<double> weights(points);
    for (double& w : weights) w = 0.1 + 0.05 * uniform(random);
    Eigen::MatrixXd values(points, size), gradients(points * size, 3);
    for (auto& v : values.reshaped()) v = uniform(random);
    for (auto& g : gradients.reshaped()) g = uniform(random);
    elements.add(basis, weights, values, gradients);
  }
  return elements;
}

struct DenseReference {
  double energy = 0;
  Eigen::VectorXd gradient;
  Eigen::MatrixXd hessian;
};

// Ψ = Σ_q w_q ψ(F_q), ∂Ψ/∂u_ai = Σ_q w_q P_ij ∂_jN_a, ∂²Ψ/∂u_ai∂u_bk = Σ_q w_q ∂P_ij/∂F_kl ∂_jN_a ∂_lN_b.
DenseReference dense_reference(const TabulatedElements& elements, const Material& material, const Eigen::VectorXd& u) {
  DenseReference reference{0, Eigen::VectorXd::Zero(u.size()), Eigen::MatrixXd::Zero(u.size(), u.size())};
  for (int e = 0; e < elements.size(); ++e) {
    const ElementView element = elements[e];
    for (int q = 0; q < element.point_count(); ++q) {
      const auto gradients = element.gradients_at(q);
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      for (int a = 0; a < element.basis_count(); ++a) F += u.segment<3>(3 * element.basis[a]) * gradients.row(a);
      Eigen::Matrix3d P;
      Matrix9d dPdF;
      material.pk1_and_tangent(F, P, dPdF);
      const double w = element.weights[q];
      reference.energy += w * material.energy(F);
      for (int a = 0; a < element.basis_count(); ++a) {
        reference.gradient.segment<3>(3 * element.basis[a]) += w * P * gradients.row(a).transpose();
        for (int b = 0; b < element.basis_count(); ++b)
          for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) {
              double sum = 0;
              for (int j = 0; j < 3; ++j)
                for (int l = 0; l < 3; ++l) sum += dPdF(i + 3 * j, k + 3 * l) * gradients(a, j) * gradients(b, l);
              reference.hessian(3 * element.basis[a] + i, 3 * element.basis[b] + k) += w * sum;
            }
      }
    }
  }
  return reference;
}

TEST(MixedSizeElements, EnergyGradientHessianAndLoadMatchDenseReferenceAndFiniteDifferences) {
  const int saved_threads = omp_get_max_threads();
  omp_set_num_threads(1);  // small: parallel regions would cost more than the work
  const TabulatedElements elements = mixed_elements(3);
  const auto material = make_material(MaterialModel::stable_neo_hookean, 1e4, 0.35, 800);
  const ElasticAssembler assembler(elements, {material.get()});
  ASSERT_EQ(assembler.dof_count(), 3 * pool_size);
  std::mt19937 random(8);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd u(assembler.dof_count());
  for (auto& value : u) value = 0.02 * uniform(random);

  const DenseReference reference = dense_reference(elements, *material, u);
  Eigen::VectorXd gradient;
  assembler.gradient(u, gradient);
  SparseMatrix hessian = assembler.pattern();
  assembler.hessian(u, hessian);
  const Eigen::MatrixXd dense(hessian);
  EXPECT_NEAR(assembler.energy(u), reference.energy, 1e-12 * std::abs(reference.energy));
  EXPECT_LT((gradient - reference.gradient).norm(), 1e-12 * reference.gradient.norm());
  EXPECT_LT((dense - reference.hessian).norm(), 1e-12 * reference.hessian.norm());

  const test::FiniteDifferences differences = test::central_differences(assembler, u, 1e-6);
  const Eigen::VectorXd& difference_gradient = differences.gradient;
  const Eigen::MatrixXd& difference_hessian = differences.hessian;
  EXPECT_LT((difference_gradient - gradient).norm(), 1e-6 * gradient.norm());
  EXPECT_LT((difference_hessian - dense).norm(), 1e-6 * dense.norm());

  // The load of a body acceleration: f_(3b+i) = Σ_q w_q ρ a_i N_b(x_q).
  const Eigen::Vector3d acceleration(0.5, -9.81, 2.0);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(u.size());
  for (int e = 0; e < elements.size(); ++e) {
    const ElementView element = elements[e];
    for (int q = 0; q < element.point_count(); ++q)
      for (int b = 0; b < element.basis_count(); ++b)
        load.segment<3>(3 * element.basis[b]) += element.weights[q] * 800 * element.values(q, b) * acceleration;
  }
  EXPECT_LT((assembler.body_force(acceleration) - load).norm(), 1e-12 * load.norm());
  omp_set_num_threads(saved_threads);
}

TEST(BlockSparsity, HoldsExactlyElementAndExtraGroupPairs) {
  const TabulatedElements elements = mixed_elements(5);
  BasisGroups extra;
  // One group reaching past the elements' basis functions (24, 25), one inside them.
  extra.add(std::vector<int>{24, 3, 25});
  extra.add(std::vector<int>{0, 23, 11, 7});
  const BlockSparsity sparsity(elements, extra);
  const SparseMatrix& pattern = sparsity.pattern();
  ASSERT_EQ(pattern.rows(), 3 * 26);

  std::set<std::pair<int, int>> expected;  // (row, column) DOF pairs
  const auto add_pairs = [&](std::span<const int> basis) {
    for (int g : basis)
      for (int h : basis)
        for (int i = 0; i < 3; ++i)
          for (int k = 0; k < 3; ++k) expected.insert({3 * h + i, 3 * g + k});
  };
  for (int e = 0; e < elements.size(); ++e) add_pairs(elements[e].basis);
  for (int g = 0; g < extra.size(); ++g) add_pairs(extra[g]);
  std::set<std::pair<int, int>> actual;
  for (int column = 0; column < pattern.outerSize(); ++column)
    for (SparseMatrix::InnerIterator it(pattern, column); it; ++it) {
      EXPECT_EQ(it.value(), 0.0);
      actual.insert({static_cast<int>(it.row()), column});
    }
  EXPECT_EQ(static_cast<size_t>(pattern.nonZeros()), actual.size());  // no duplicates
  EXPECT_EQ(actual, expected);

  // Every offset names the row 3·g_a inside column 3·g_b + k.
  const auto check_offsets = [&](std::span<const int> basis, const int* offsets) {
    const int n = static_cast<int>(basis.size());
    for (int b = 0; b < n; ++b)
      for (int k = 0; k < 3; ++k)
        for (int a = 0; a < n; ++a)
          for (int i = 0; i < 3; ++i)
            ASSERT_EQ(pattern.innerIndexPtr()[pattern.outerIndexPtr()[3 * basis[b] + k] + offsets[b * n + a] + i],
                      3 * basis[a] + i);
  };
  for (int e = 0; e < elements.size(); ++e) check_offsets(elements[e].basis, sparsity.pair_offsets(e));
  for (int g = 0; g < extra.size(); ++g) check_offsets(extra[g], sparsity.extra_pair_offsets(g));
}

}  // namespace
}  // namespace altfem
