// TwoLevelPreconditioner (Dobrev, Lazarov, Vassilevski & Zikatanov 2006): both cycles are
// symmetric positive definite on random vectors, and the coarse correction alone (damping 0)
// inverts A exactly on the coarse space, even when P has dependent columns (the shifted A_c);
// a V-cycle as coarse solve (three levels, Gauss–Seidel sweeps forward before and backward
// after) stays symmetric positive definite; the additive cycle refuses a one-way sweep.
#include <gtest/gtest.h>

#include "shared/solve/block_relaxation_preconditioner.hpp"
#include "shared/solve/two_level_preconditioner.hpp"
#include "tests/unit/random_vectors.hpp"
#include "tests/unit/solve/preconditioner_checks.hpp"
#include "tests/unit/solve/test_matrices.hpp"

namespace altfem {
namespace {

constexpr int grid = 6;  // elasticity_like_laplacian(6): 3 · 6³ unknowns

// Piecewise constants on 2 × 2 × 2 aggregates of the grid's nodes, per component, and one
// column repeated (P with dependent columns): 3 · 27 + 1 columns.
Eigen::SparseMatrix<double> aggregate_prolongation() {
  std::vector<Eigen::Triplet<double>> entries;
  const int aggregates = grid / 2;
  for (int k = 0; k < grid; ++k)
    for (int j = 0; j < grid; ++j)
      for (int i = 0; i < grid; ++i) {
        const int node = i + grid * (j + grid * k);
        const int aggregate = i / 2 + aggregates * (j / 2 + aggregates * (k / 2));
        for (int c = 0; c < 3; ++c) entries.emplace_back(3 * node + c, 3 * aggregate + c, 1.0);
        if (aggregate == 0) entries.emplace_back(3 * node, 3 * aggregates * aggregates * aggregates, 1.0);
      }
  Eigen::SparseMatrix<double> prolongation(3 * grid * grid * grid, 3 * aggregates * aggregates * aggregates + 1);
  prolongation.setFromTriplets(entries.begin(), entries.end());
  return prolongation;
}

TwoLevelPreconditioner two_level(TwoLevelCycle cycle, double damping) {
  return TwoLevelPreconditioner(make_preconditioner("jacobi"), aggregate_prolongation(), cycle, damping);
}

class TwoLevelCycles : public ::testing::TestWithParam<TwoLevelCycle> {};

TEST_P(TwoLevelCycles, IsSymmetricPositiveDefinite) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(grid);
  // Jacobi on this matrix has λ_max(D⁻¹A) < 2: ω = 0.7 makes the V-cycle's smoother convergent.
  TwoLevelPreconditioner preconditioner = two_level(GetParam(), 0.7);
  preconditioner.compute(matrix);
  testing::expect_symmetric_positive_definite(preconditioner, matrix.rows());
}

TEST_P(TwoLevelCycles, CoarseCorrectionIsExactOnTheCoarseSpace) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(grid);
  TwoLevelPreconditioner preconditioner = two_level(GetParam(), 0.0);  // no smoothing: P A_c⁻¹ Pᵀ
  preconditioner.compute(matrix);
  const Eigen::SparseMatrix<double> prolongation = aggregate_prolongation();
  const Eigen::VectorXd coarse = test::random_vector(prolongation.cols(), 7);
  const Eigen::VectorXd solution = prolongation * coarse;
  Eigen::VectorXd applied;
  preconditioner.apply(matrix * solution, applied);
  EXPECT_LT((applied - solution).norm(), 1e-8 * solution.norm());
}

// The aggregates' prolongation's 3 · 27 + 1 columns, 3 per aggregate, to 3 · 1: all
// aggregates into one (per component), the extra column dropped.
Eigen::SparseMatrix<double> single_aggregate_prolongation() {
  const int aggregates = grid / 2;
  std::vector<Eigen::Triplet<double>> entries;
  for (int a = 0; a < aggregates * aggregates * aggregates; ++a)
    for (int c = 0; c < 3; ++c) entries.emplace_back(3 * a + c, c, 1.0);
  Eigen::SparseMatrix<double> prolongation(3 * aggregates * aggregates * aggregates + 1, 3);
  prolongation.setFromTriplets(entries.begin(), entries.end());
  return prolongation;
}

std::vector<int> triples(Eigen::Index dofs) {
  std::vector<int> starts;
  for (int first = 0; first <= dofs; first += 3) starts.push_back(first);
  return starts;
}

TEST(TwoLevelPreconditioner, AVCycleAsCoarseSolveIsSymmetricPositiveDefinite) {
  const Eigen::SparseMatrix<double> matrix = testing::elasticity_like_laplacian(grid);
  const Eigen::SparseMatrix<double> middle = aggregate_prolongation();
  ASSERT_THROW(TwoLevelPreconditioner(std::make_unique<BlockRelaxationPreconditioner>(triples(matrix.rows()),
                                                                                      BlockRelaxation::gauss_seidel),
                                      middle, TwoLevelCycle::additive),
               std::logic_error);
  // The middle level has 3 · 27 + 1 unknowns: the extra one makes a last block of 1.
  std::vector<int> middle_blocks = triples(middle.cols() - 1);
  middle_blocks.push_back(static_cast<int>(middle.cols()));
  auto coarse = std::make_unique<TwoLevelPreconditioner>(
      std::make_unique<BlockRelaxationPreconditioner>(middle_blocks, BlockRelaxation::gauss_seidel),
      single_aggregate_prolongation(), TwoLevelCycle::multiplicative, 1.0);
  TwoLevelPreconditioner three_levels(
      std::make_unique<BlockRelaxationPreconditioner>(triples(matrix.rows()), BlockRelaxation::gauss_seidel), middle,
      TwoLevelCycle::multiplicative, 1.0, std::move(coarse));
  three_levels.compute(matrix);
  EXPECT_EQ(three_levels.coarse_statistics().factorisations, 0);  // the V-cycle, not CHOLMOD, below
  testing::expect_symmetric_positive_definite(three_levels, matrix.rows());
}

INSTANTIATE_TEST_SUITE_P(TwoLevelPreconditioner, TwoLevelCycles,
                         ::testing::Values(TwoLevelCycle::additive, TwoLevelCycle::multiplicative),
                         [](const ::testing::TestParamInfo<TwoLevelCycle>& info) {
                           return info.param == TwoLevelCycle::additive ? "additive" : "multiplicative";
                         });

}  // namespace
}  // namespace altfem
