// AdditiveSchwarzPreconditioner (Longva et al. 2020 §5.2): S against the dense matrix
// of eq. (13) built here from its definition, positive definiteness on indefinite
// systems (eq. (14)'s reflection), the ε replacement of tiny eigenvalues, and the
// condition number it buys on a nearly singular block.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "shared/common/eigen_decompositions.hpp"
#include "shared/common/error.hpp"
#include "shared/solve/additive_schwarz_preconditioner.hpp"

namespace altfem {
namespace {

// A random symmetric matrix (#n × #n) with eigenvalues `spectrum`.
Eigen::MatrixXd with_spectrum(const Eigen::VectorXd& spectrum, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd gaussian(spectrum.size(), spectrum.size());
  for (Eigen::Index i = 0; i < gaussian.size(); ++i) gaussian.data()[i] = normal(random);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(gaussian);
  const Eigen::MatrixXd Q = qr.householderQ();
  return Q * spectrum.asDiagonal() * Q.transpose();
}

// S as a dense matrix, column by column.
Eigen::MatrixXd dense(const AdditiveSchwarzPreconditioner& preconditioner, Eigen::Index n) {
  Eigen::MatrixXd S(n, n);
  Eigen::VectorXd column;
  for (Eigen::Index j = 0; j < n; ++j) {
    preconditioner.apply(Eigen::VectorXd::Unit(n, j), column);
    S.col(j) = column;
  }
  return S;
}

// Eq. (13) with eq. (14), from the definition.
Eigen::MatrixXd expected_schwarz(const Eigen::MatrixXd& C, const std::vector<std::vector<int>>& blocks,
                                 double epsilon) {
  const Eigen::Index n = C.rows();
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n, n);
  std::vector<bool> covered(n, false);
  for (const auto& block : blocks) {
    const auto m = static_cast<Eigen::Index>(block.size());
    Eigen::MatrixXd local(m, m);
    for (Eigen::Index i = 0; i < m; ++i)
      for (Eigen::Index j = 0; j < m; ++j) local(i, j) = C(block[i], block[j]);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(local);
    const double largest = eigen.eigenvalues().cwiseAbs().maxCoeff();
    Eigen::VectorXd mu(m);
    for (Eigen::Index k = 0; k < m; ++k) {
      const double magnitude = std::abs(eigen.eigenvalues()[k]);
      mu[k] = magnitude >= epsilon * largest ? 1 / magnitude : epsilon / largest;
    }
    const Eigen::MatrixXd inverse = eigen.eigenvectors() * mu.asDiagonal() * eigen.eigenvectors().transpose();
    for (Eigen::Index i = 0; i < m; ++i) {
      covered[block[i]] = true;
      for (Eigen::Index j = 0; j < m; ++j) S(block[i], block[j]) += inverse(i, j);
    }
  }
  for (Eigen::Index i = 0; i < n; ++i)
    if (!covered[i]) S(i, i) = 1 / std::abs(C(i, i));
  return S;
}

Eigen::SparseMatrix<double> sparse(const Eigen::MatrixXd& matrix) { return matrix.sparseView(); }

TEST(AdditiveSchwarz, MatchesEquation13WithOverlappingBlocksAndDiagonalRest) {
  Eigen::VectorXd spectrum = Eigen::VectorXd::LinSpaced(12, 1.0, 30.0);
  const Eigen::MatrixXd C = with_spectrum(spectrum, 3);
  const std::vector<std::vector<int>> blocks{{0, 1, 2, 3}, {3, 4, 5, 6, 7}, {9, 8}};  // 10, 11 diagonal
  AdditiveSchwarzPreconditioner preconditioner(blocks);
  preconditioner.compute(sparse(C));
  EXPECT_EQ(preconditioner.block_count(), 3);
  EXPECT_LT((dense(preconditioner, 12) - expected_schwarz(C, blocks, 1e-13)).cwiseAbs().maxCoeff(), 1e-12);
}

// The structural bound a multigrid's Chebyshev smoother takes: DOF 3 lies in three blocks,
// so e_3's Rayleigh quotient of S C (in C's inner product) is at least 3, and so is the
// largest eigenvalue of S C. On one process the shares are the whole, and
// compute_from_shares is compute.
TEST(AdditiveSchwarz, LargestEigenvalueReachesTheMostBlocksHoldingOneDof) {
  const Eigen::MatrixXd C = with_spectrum(Eigen::VectorXd::LinSpaced(12, 1.0, 30.0), 7);
  const std::vector<std::vector<int>> blocks{{0, 1, 2, 3}, {3, 4, 5}, {2, 3, 6, 7}, {9, 8}};
  AdditiveSchwarzPreconditioner preconditioner(blocks), from_shares(blocks);
  preconditioner.compute(sparse(C));
  from_shares.compute_from_shares(sparse(C));
  EXPECT_EQ(preconditioner.largest_eigenvalue_at_least(), 3);
  const Eigen::MatrixXd S = dense(preconditioner, 12);
  EXPECT_EQ((dense(from_shares, 12) - S).cwiseAbs().maxCoeff(), 0.0);
  const Eigen::VectorXd e = Eigen::VectorXd::Unit(12, 3);
  EXPECT_GE((C * e).dot(S * C * e) / e.dot(C * e), 3 * (1 - 1e-12));
  // S C is similar to the symmetric C^½ S C^½: its largest eigenvalue is real.
  const Eigen::VectorXcd eigenvalues = Eigen::EigenSolver<Eigen::MatrixXd>(S * C).eigenvalues();
  EXPECT_GE(eigenvalues.real().maxCoeff(), 3 * (1 - 1e-12));
  AdditiveSchwarzPreconditioner disjoint({{0, 1}, {2, 3}});
  disjoint.compute(sparse(C));
  EXPECT_EQ(disjoint.largest_eigenvalue_at_least(), 1);
}

TEST(AdditiveSchwarz, DisjointBlocksCoveringEveryDofInvertABlockDiagonalMatrix) {
  // Block Jacobi (DG, one block per element): exact for a block-diagonal matrix.
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(7, 7);
  C.block(0, 0, 3, 3) = with_spectrum(Eigen::Vector3d(1, 2, 5), 1);
  C.block(3, 3, 4, 4) = with_spectrum(Eigen::Vector4d(0.5, 3, 4, 9), 2);
  AdditiveSchwarzPreconditioner preconditioner({{0, 1, 2}, {3, 4, 5, 6}});
  preconditioner.compute(sparse(C));
  EXPECT_LT((dense(preconditioner, 7) * C - Eigen::MatrixXd::Identity(7, 7)).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(AdditiveSchwarz, StaysPositiveDefiniteOnAnIndefiniteMatrix) {
  Eigen::VectorXd spectrum(8);
  spectrum << -3, -1, 0.5, 1, 2, 4, 6, 8;
  const Eigen::MatrixXd C = with_spectrum(spectrum, 5);
  AdditiveSchwarzPreconditioner preconditioner({{0, 1, 2, 3, 4}, {4, 5, 6, 7}});
  preconditioner.compute(sparse(C));
  const Eigen::MatrixXd S = dense(preconditioner, 8);
  EXPECT_LT((S - S.transpose()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(S).eigenvalues().minCoeff(), 0.0);
}

TEST(AdditiveSchwarz, ReplacesEigenvaluesBelowEpsilonTimesTheLargest) {
  Eigen::MatrixXd C = with_spectrum(Eigen::Vector3d(2.0, 1.0, 1e-20), 7);
  AdditiveSchwarzPreconditioner preconditioner({{0, 1, 2}}, 1e-13);
  preconditioner.compute(sparse(C));
  EXPECT_EQ(preconditioner.reflected_small_eigenvalues(), 1);
  const Eigen::VectorXd eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense(preconditioner, 3)).eigenvalues();
  EXPECT_NEAR(eigenvalues.minCoeff(), 1e-13 / 2.0, 1e-15);  // ε / λ_max (to round-off of S), not 1e20
  EXPECT_NEAR(eigenvalues.maxCoeff(), 1.0, 1e-12);
}

TEST(AdditiveSchwarz, RestoresTheConditionOfNearlyDependentFunctions) {
  // Two nearly dependent functions (Longva et al. §5.1): κ(C) ≈ 1e12, but one Schwarz
  // block over them brings κ(SC) to 1.
  Eigen::MatrixXd C = with_spectrum(Eigen::Vector2d(1.0, 1e-12), 11);
  const Eigen::VectorXd plain = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(C).eigenvalues();
  EXPECT_GT(plain.maxCoeff() / plain.minCoeff(), 1e11);
  AdditiveSchwarzPreconditioner preconditioner({{0, 1}});
  preconditioner.compute(sparse(C));
  const Eigen::VectorXcd preconditioned =
      Eigen::EigenSolver<Eigen::MatrixXd>(dense(preconditioner, 2) * C).eigenvalues();
  EXPECT_NEAR(preconditioned.cwiseAbs().maxCoeff() / preconditioned.cwiseAbs().minCoeff(), 1.0, 1e-3);
}

TEST(AdditiveSchwarz, ZeroDiagonalOutsideBlocksIsANumericalError) {
  Eigen::MatrixXd C = Eigen::MatrixXd::Identity(3, 3);
  C(2, 2) = 0;
  AdditiveSchwarzPreconditioner preconditioner({{0, 1}});
  EXPECT_THROW(preconditioner.compute(sparse(C)), NumericalError);
}

}  // namespace
}  // namespace altfem
