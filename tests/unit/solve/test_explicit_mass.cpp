// The explicit masses (issue #14, item 4): a positive diagonal, and a block-diagonal
// consistent mass inverted block by block, with the checks that make the inverse exact.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "shared/common/eigen_decompositions.hpp"
#include "shared/solve/explicit_mass.hpp"
#include "tests/unit/random_vectors.hpp"

namespace altfem {
namespace {

using test::random_vector;

TEST(DiagonalMass, MultiplySolveRoundTripAndKineticEnergy) {
  const Eigen::VectorXd diagonal = random_vector(12, 1).array().abs() + 0.1;
  const DiagonalMass mass(diagonal);
  const Eigen::VectorXd v = random_vector(12, 2);
  EXPECT_LT((mass.solve(mass.multiply(v)) - v).norm(), 1e-14 * v.norm());
  EXPECT_NEAR(mass.kinetic_energy(v), 0.5 * (diagonal.array() * v.array().square()).sum(), 1e-14);
  Eigen::VectorXd with_zero = diagonal;
  with_zero[5] = 0;
  EXPECT_THROW(DiagonalMass{with_zero}, std::invalid_argument);
}

// 9 DOFs in the groups {0, 4, 8}, {1, 2, 3, 5}, {6, 7}: a random SPD block per group,
// scattered into a sparse matrix with explicit zeros in one cross-group position (a
// shared pattern holds them; they are not a coupling).
struct BlockMassCase {
  std::vector<std::vector<int>> groups{{0, 4, 8}, {1, 2, 3, 5}, {6, 7}};
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(9, 9);

  BlockMassCase() {
    unsigned seed = 3;
    for (const auto& group : groups) {
      const auto n = static_cast<Eigen::Index>(group.size());
      const Eigen::MatrixXd A = random_vector(n * n, seed++).reshaped(n, n);
      const Eigen::MatrixXd block = A * A.transpose() + 0.5 * Eigen::MatrixXd::Identity(n, n);
      for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j) dense(group[i], group[j]) = block(i, j);
    }
  }
  Eigen::SparseMatrix<double> sparse() const {
    std::vector<Eigen::Triplet<double>> entries{{0, 1, 0.0}, {1, 0, 0.0}};
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j)
        if (dense(i, j) != 0) entries.emplace_back(i, j, dense(i, j));
    Eigen::SparseMatrix<double> matrix(9, 9);
    matrix.setFromTriplets(entries.begin(), entries.end());
    return matrix;
  }
};

TEST(BlockDiagonalMass, SolveInvertsMultiplyAndMultiplyIsTheMatrix) {
  const BlockMassCase block_case;
  const BlockDiagonalMass mass(block_case.sparse(), block_case.groups);
  const Eigen::VectorXd v = random_vector(9, 10);
  EXPECT_LT((mass.multiply(v) - block_case.dense * v).norm(), 1e-14 * v.norm());
  EXPECT_LT((mass.solve(mass.multiply(v)) - v).norm(), 1e-12 * v.norm());
  EXPECT_LT((mass.solve(v) - block_case.dense.llt().solve(v)).norm(), 1e-12 * mass.solve(v).norm());
}

TEST(BlockDiagonalMass, RejectsCouplingOverlapMissingDofsAndIndefiniteBlocks) {
  const BlockMassCase block_case;
  Eigen::SparseMatrix<double> coupled = block_case.sparse();
  coupled.coeffRef(0, 1) = 1e-3;  // DOFs 0 and 1 lie in different groups
  EXPECT_THROW(BlockDiagonalMass(coupled, block_case.groups), std::invalid_argument);

  auto overlapping = block_case.groups;
  overlapping[2].push_back(8);
  EXPECT_THROW(BlockDiagonalMass(block_case.sparse(), overlapping), std::invalid_argument);
  auto missing = block_case.groups;
  missing[1].pop_back();
  EXPECT_THROW(BlockDiagonalMass(block_case.sparse(), missing), std::invalid_argument);
  auto out_of_range = block_case.groups;
  out_of_range[2].push_back(9);
  EXPECT_THROW(BlockDiagonalMass(block_case.sparse(), out_of_range), std::invalid_argument);

  Eigen::SparseMatrix<double> indefinite = block_case.sparse();
  indefinite.coeffRef(6, 6) = -1.0;
  EXPECT_THROW(BlockDiagonalMass(indefinite, block_case.groups), std::invalid_argument);
}

}  // namespace
}  // namespace altfem
