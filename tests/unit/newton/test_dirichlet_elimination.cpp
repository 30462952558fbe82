// DirichletElimination: the eliminated system gives the prescribed increments
// exactly and the free part of the reduced (Schur-free) system K_ff Δu_f = r_f − K_fc Δc.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <random>

#include "shared/common/eigen_decompositions.hpp"
#include "shared/solve/dirichlet_elimination.hpp"

namespace altfem {
namespace {

struct System {
  Eigen::MatrixXd dense;
  Eigen::SparseMatrix<double> sparse;
};

// A random symmetric n × n matrix with a banded pattern (bandwidth 3); SPD when
// `shift` is large enough.
System random_system(int n, double shift, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = i; j < std::min(n, i + 4); ++j) dense(i, j) = dense(j, i) = uniform(random);
  dense.diagonal().array() += shift;
  return {dense, dense.sparseView()};
}

const std::vector<int> constrained{1, 4, 5, 8};

std::vector<int> free_dofs(int n) {
  std::vector<int> free;
  for (int i = 0; i < n; ++i)
    if (std::find(constrained.begin(), constrained.end(), i) == constrained.end()) free.push_back(i);
  return free;
}

void check_elimination(const System& system) {
  const int n = static_cast<int>(system.dense.rows());
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd rhs(n), increment(static_cast<Eigen::Index>(constrained.size()));
  for (auto& value : rhs) value = uniform(random);
  for (auto& value : increment) value = uniform(random);

  const DirichletElimination elimination(system.sparse, {8, 1, 5, 4});  // any order in, sorted inside
  EXPECT_EQ(elimination.constrained_dofs(), constrained);
  Eigen::SparseMatrix<double> matrix = system.sparse;
  Eigen::VectorXd eliminated_rhs = rhs;
  elimination.apply(matrix, eliminated_rhs, increment);
  EXPECT_EQ(matrix.nonZeros(), system.sparse.nonZeros());  // one pattern for the whole run
  const Eigen::MatrixXd eliminated(matrix);
  EXPECT_EQ(eliminated, eliminated.transpose());
  const Eigen::VectorXd solution = eliminated.fullPivLu().solve(eliminated_rhs);

  for (size_t i = 0; i < constrained.size(); ++i)
    EXPECT_NEAR(solution[constrained[i]], increment[static_cast<Eigen::Index>(i)], 1e-14);
  EXPECT_EQ(elimination.constrained_values(solution).size(), increment.size());

  // The reduced dense system.
  const std::vector<int> free = free_dofs(n);
  const auto f = static_cast<Eigen::Index>(free.size()), c = static_cast<Eigen::Index>(constrained.size());
  Eigen::MatrixXd K_ff(f, f), K_fc(f, c);
  Eigen::VectorXd r_f(f);
  for (Eigen::Index i = 0; i < f; ++i) {
    r_f[i] = rhs[free[i]];
    for (Eigen::Index j = 0; j < f; ++j) K_ff(i, j) = system.dense(free[i], free[j]);
    for (Eigen::Index j = 0; j < c; ++j) K_fc(i, j) = system.dense(free[i], constrained[j]);
  }
  const Eigen::VectorXd reduced = K_ff.fullPivLu().solve(r_f - K_fc * increment);
  for (Eigen::Index i = 0; i < f; ++i) EXPECT_NEAR(solution[free[i]], reduced[i], 1e-12 * reduced.norm());
}

TEST(DirichletElimination, SpdSystemGivesPrescribedAndReducedSolution) {
  const System system = random_system(10, 6.0, 1);
  ASSERT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(system.dense).eigenvalues().minCoeff(), 0.0);
  check_elimination(system);
}

TEST(DirichletElimination, NonPositiveConstrainedDiagonalStillExact) {
  // An indefinite tangent may have a negative diagonal at a constrained DOF; the
  // elimination replaces it and Δu_c = Δc must still hold.
  System system = random_system(10, 6.0, 2);
  system.dense(4, 4) = -0.5;
  system.dense(5, 5) = 0.0;
  system.sparse = system.dense.sparseView();
  system.sparse.coeffRef(5, 5) = 0.0;  // keep the diagonal entry in the pattern
  system.sparse.makeCompressed();
  check_elimination(system);
}

TEST(DirichletElimination, NormsAndConstrainedValues) {
  const System system = random_system(10, 6.0, 3);
  const DirichletElimination elimination(system.sparse, constrained);
  Eigen::VectorXd vector = Eigen::VectorXd::LinSpaced(10, 1.0, 10.0);
  double free_squares = 0;
  for (int i : free_dofs(10)) free_squares += vector[i] * vector[i];
  EXPECT_DOUBLE_EQ(elimination.free_norm(vector), std::sqrt(free_squares));
  const Eigen::Vector4d values(-1, -2, -3, -4);
  elimination.set_constrained(vector, values);
  EXPECT_EQ(elimination.constrained_values(vector), Eigen::VectorXd(values));
  EXPECT_TRUE(elimination.is_constrained(8));
  EXPECT_FALSE(elimination.is_constrained(0));
}

}  // namespace
}  // namespace altfem
