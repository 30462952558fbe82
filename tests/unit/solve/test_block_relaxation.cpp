// BlockRelaxationPreconditioner: Jacobi inverts the block diagonal exactly; a Gauss–Seidel
// sweep's apply_transpose is its exact transpose; the symmetric sweep is symmetric positive
// definite, in the blocks' order and in colours (2 on a chain, whose multicolour sweeps keep
// that algebra); iterating x ← x + M⁻¹(b − Ax) converges on an SPD matrix (Gauss–Seidel's
// classic guarantee); and a block that is not positive definite is named.
#include <gtest/gtest.h>

#include <omp.h>

#include <Eigen/Dense>

#include "shared/common/error.hpp"
#include "shared/solve/block_relaxation_preconditioner.hpp"
#include "tests/unit/random_vectors.hpp"
#include "tests/unit/solve/preconditioner_checks.hpp"
#include "tests/unit/solve/test_matrices.hpp"

namespace altfem {
namespace {

constexpr int grid = 5;  // elasticity_like_laplacian(5): 3 · 5³ unknowns, a node's 3 a block

std::vector<int> node_blocks(Eigen::Index dofs, int size) {
  std::vector<int> starts;
  for (int first = 0; first <= dofs; first += size) starts.push_back(first);
  return starts;
}

TEST(BlockRelaxation, JacobiInvertsTheBlockDiagonal) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(grid);
  BlockRelaxationPreconditioner jacobi(node_blocks(matrix.rows(), 3), BlockRelaxation::jacobi);
  jacobi.compute(matrix);
  const Eigen::VectorXd x = test::random_vector(matrix.rows(), 3);
  Eigen::VectorXd block_diagonal_x = Eigen::VectorXd::Zero(matrix.rows()), applied;
  const Eigen::MatrixXd dense = matrix;
  for (Eigen::Index first = 0; first < matrix.rows(); first += 3)
    block_diagonal_x.segment<3>(first) = dense.block<3, 3>(first, first) * x.segment<3>(first);
  jacobi.apply(block_diagonal_x, applied);
  EXPECT_LT((applied - x).norm(), 1e-13 * x.norm());
  EXPECT_TRUE(jacobi.symmetric());
}

TEST(BlockRelaxation, ForwardSweepsTransposeIsTheBackwardSweep) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(grid);
  BlockRelaxationPreconditioner sweep(node_blocks(matrix.rows(), 3), BlockRelaxation::gauss_seidel);
  sweep.compute(matrix);
  EXPECT_FALSE(sweep.symmetric());
  Eigen::VectorXd forward, backward, symmetric_part;
  const Eigen::VectorXd x = test::random_vector(matrix.rows(), 1), y = test::random_vector(matrix.rows(), 2);
  sweep.apply(x, forward);
  sweep.apply_transpose(y, backward);
  EXPECT_NEAR(y.dot(forward), backward.dot(x), 1e-12 * y.norm() * forward.norm());
  // …and not symmetric itself: M⁻¹ ≠ M⁻ᵀ (else the test above proved nothing).
  Eigen::VectorXd forward_y;
  sweep.apply(y, forward_y);
  EXPECT_GT(std::abs(y.dot(forward) - x.dot(forward_y)), 1e-6 * y.norm() * forward.norm());
}

TEST(BlockRelaxation, SymmetricSweepIsSymmetricPositiveDefinite) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(grid);
  BlockRelaxationPreconditioner sweep(node_blocks(matrix.rows(), 3), BlockRelaxation::symmetric_gauss_seidel);
  sweep.compute(matrix);
  EXPECT_TRUE(sweep.symmetric());
  testing::expect_symmetric_positive_definite(sweep, matrix.rows());
}

TEST(BlockRelaxation, SweepsThatKeepTheDefectMatchTheOnesThatDoNot) {
  // Blocks of 3 (the vertex fast path) and of 6 (the general one).
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(grid);
  for (int size : {3, 6})
    for (BlockRelaxation relaxation : {BlockRelaxation::gauss_seidel, BlockRelaxation::symmetric_gauss_seidel}) {
      std::vector<int> starts = node_blocks(matrix.rows() - matrix.rows() % size, size);
      if (starts.back() != matrix.rows()) starts.push_back(static_cast<int>(matrix.rows()));
      BlockRelaxationPreconditioner sweep(starts, relaxation);
      sweep.compute(matrix);
      const Eigen::VectorXd residual = test::random_vector(matrix.rows(), 4);
      Eigen::VectorXd plain, kept, defect;
      sweep.apply(residual, plain);
      ASSERT_TRUE(sweep.apply_with_defect(residual, kept, defect)) << "blocks of " << size;  // few blocks: one thread
      EXPECT_LT((kept - plain).norm(), 1e-13 * plain.norm()) << "blocks of " << size;
      const Eigen::VectorXd expected = residual - matrix * kept;
      EXPECT_LT((defect - expected).norm(), 1e-12 * residual.norm()) << "blocks of " << size;
    }
  BlockRelaxationPreconditioner jacobi(node_blocks(matrix.rows(), 3), BlockRelaxation::jacobi);
  jacobi.compute(matrix);
  Eigen::VectorXd result, defect;
  EXPECT_FALSE(jacobi.apply_with_defect(Eigen::VectorXd::Ones(matrix.rows()), result, defect));
}

// A tridiagonal chain of 2 × 2 blocks, long enough to be swept in parallel (multicolour).
Eigen::SparseMatrix<double> block_chain(int blocks) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int b = 0; b < blocks; ++b)
    for (int i = 0; i < 2; ++i) {
      entries.emplace_back(2 * b + i, 2 * b + i, 4.0);
      entries.emplace_back(2 * b + i, 2 * b + 1 - i, 1.0);
      if (b + 1 < blocks) {
        entries.emplace_back(2 * b + i, 2 * (b + 1) + i, -1.0);
        entries.emplace_back(2 * (b + 1) + i, 2 * b + i, -1.0);
      }
    }
  Eigen::SparseMatrix<double> chain(2 * blocks, 2 * blocks);
  chain.setFromTriplets(entries.begin(), entries.end());
  return chain;
}

// Runs `body` with two OpenMP threads, then restores the previous count.
template <class Body>
void with_two_threads(Body body) {
  const int previous = omp_get_max_threads();
  omp_set_num_threads(2);
  body();
  omp_set_num_threads(previous);
}

TEST(BlockRelaxation, SweepsInColoursWhenThereAreThreadsAndBlocksToShare) {
  with_two_threads([] {
    // Neighbours alternate along a chain: two colours suffice, and one would couple blocks.
    const Eigen::SparseMatrix<double> chain = block_chain(10000);
    BlockRelaxationPreconditioner sweep(node_blocks(chain.rows(), 2), BlockRelaxation::gauss_seidel);
    sweep.compute(chain);
    EXPECT_EQ(sweep.colour_count(), 2);
    // The multicolour sweeps keep their algebra: the backward one is the forward one's transpose,
    // the symmetric one symmetric positive definite.
    const Eigen::VectorXd x = test::random_vector(chain.rows(), 1), y = test::random_vector(chain.rows(), 2);
    Eigen::VectorXd forward, backward;
    sweep.apply(x, forward);
    sweep.apply_transpose(y, backward);
    EXPECT_NEAR(y.dot(forward), backward.dot(x), 1e-12 * y.norm() * forward.norm());
    Eigen::VectorXd defect;
    EXPECT_FALSE(sweep.apply_with_defect(x, forward, defect));  // two threads may share a neighbour
    BlockRelaxationPreconditioner symmetric(node_blocks(chain.rows(), 2), BlockRelaxation::symmetric_gauss_seidel);
    symmetric.compute(chain);
    testing::expect_symmetric_positive_definite(symmetric, chain.rows(), 2);
  });
  // Few blocks: one thread, in the blocks' own order.
  const Eigen::SparseMatrix<double> short_chain = block_chain(10);
  BlockRelaxationPreconditioner sweep(node_blocks(short_chain.rows(), 2), BlockRelaxation::gauss_seidel);
  sweep.compute(short_chain);
  EXPECT_EQ(sweep.colour_count(), 0);
}

TEST(BlockRelaxation, StationaryIterationConvergesOnAnSpdMatrix) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(grid);
  const Eigen::VectorXd solution = test::random_vector(matrix.rows(), 9);
  const Eigen::VectorXd rhs = matrix * solution;
  for (BlockRelaxation relaxation : {BlockRelaxation::gauss_seidel, BlockRelaxation::symmetric_gauss_seidel}) {
    BlockRelaxationPreconditioner sweep(node_blocks(matrix.rows(), 3), relaxation);
    sweep.compute(matrix);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(matrix.rows()), correction;
    double previous = (solution - x).norm();
    for (int iteration = 0; iteration < 30; ++iteration) {
      sweep.apply(rhs - matrix * x, correction);
      x += correction;
      const double error = (solution - x).norm();
      EXPECT_LT(error, previous) << "iteration " << iteration;
      previous = error;
    }
    EXPECT_LT(previous, 0.1 * solution.norm());
  }
}

TEST(BlockRelaxation, ABlockThatIsNotPositiveDefiniteIsNamed) {
  Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(3);
  matrix.coeffRef(7, 7) = -1.0;  // in block 2 (DOFs 6-8)
  BlockRelaxationPreconditioner jacobi(node_blocks(matrix.rows(), 3), BlockRelaxation::jacobi);
  try {
    jacobi.compute(matrix);
    FAIL() << "expected a NumericalError";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("block 2 (DOFs 6-8)"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace altfem
