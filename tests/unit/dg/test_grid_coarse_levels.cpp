// grid_coarse_levels: every level's trilinear interpolation reproduces affine fields exactly
// (rows sum to 1), nodes nested in a grid take their own node's value alone, the spacing
// doubles until the coarsest grid has at most the requested nodes, and on DG's hexahedral
// grid the first level is the 2h grid.
#include <gtest/gtest.h>

#include "dg/dg_linear_system.hpp"
#include "dg/grid_coarse_levels.hpp"
#include "dg/polyhedral_mesh_faces.hpp"
#include "shared/common/eigen_decompositions.hpp"
#include "shared/mesh/polyhedral_from_volume_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem::dg {
namespace {

// An affine vector field's values at points (#points × 3), interleaved as the prolongations' columns.
Eigen::VectorXd affine_values(const Eigen::MatrixXd& points) {
  Eigen::Matrix3d gradient;
  gradient << 0.3, -1.2, 0.7, 2.1, 0.4, -0.5, -0.9, 1.6, 0.2;
  const Eigen::Vector3d shift(0.25, -0.5, 1.5);
  Eigen::VectorXd values(3 * points.rows());
  for (Eigen::Index p = 0; p < points.rows(); ++p)
    values.segment<3>(3 * p) = gradient * points.row(p).transpose() + shift;
  return values;
}

// Scattered points (a distorted lattice) in [0, 1.3] × [0, 0.7] × [0, 2].
Eigen::MatrixXd scattered_points() {
  Eigen::MatrixXd points(13 * 7 * 20, 3);
  int p = 0;
  for (int k = 0; k < 20; ++k)
    for (int j = 0; j < 7; ++j)
      for (int i = 0; i < 13; ++i)
        points.row(p++) << 0.1 * i + 0.03 * std::sin(7.0 * j + k), 0.1 * j + 0.02 * std::cos(3.0 * i),
            0.1 * k + 0.01 * std::sin(5.0 * i + j);
  return points;
}

TEST(GridCoarseLevels, EveryLevelReproducesAffineFields) {
  const Eigen::MatrixXd points = scattered_points();
  const std::vector<Eigen::SparseMatrix<double>> levels = grid_coarse_levels(points, 0.2, 50);
  ASSERT_GE(levels.size(), 2u);
  // Walk down: each level's nodes are recovered from its prolongation's structure, so test
  // instead the composed prolongation on the affine field evaluated at the coarsest nodes:
  // P₀ P₁ … reproduces it at the points iff every level does. The coarsest nodes' positions
  // are the least-squares solution of (P₀ ⋯ P_L) X = points per coordinate, exact when the
  // interpolations reproduce affine fields.
  Eigen::SparseMatrix<double> composed = levels[0];
  for (size_t l = 1; l < levels.size(); ++l) composed = composed * levels[l];
  for (const auto& level : levels) {
    const Eigen::VectorXd row_sums = level * Eigen::VectorXd::Ones(level.cols());
    EXPECT_LT((row_sums - Eigen::VectorXd::Ones(level.rows())).cwiseAbs().maxCoeff(), 1e-12);
  }
  const Eigen::MatrixXd dense = composed;
  Eigen::MatrixXd x_coordinates(points.rows(), 3), solved(composed.cols() / 3, 3);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> least_squares(dense);
  Eigen::VectorXd interleaved(3 * points.rows());
  for (Eigen::Index p = 0; p < points.rows(); ++p) interleaved.segment<3>(3 * p) = points.row(p).transpose();
  const Eigen::VectorXd nodes = least_squares.solve(interleaved);
  EXPECT_LT((dense * nodes - interleaved).norm(), 1e-10 * interleaved.norm());
  for (Eigen::Index n = 0; n < solved.rows(); ++n) solved.row(n) = nodes.segment<3>(3 * n).transpose();
  EXPECT_LT((composed * affine_values(solved) - affine_values(points)).norm(), 1e-10 * affine_values(points).norm());
  EXPECT_LE(composed.cols() / 3, 50);
  EXPECT_GT(levels[levels.size() - 2].cols() / 3, 50);  // the level above the coarsest had more
}

TEST(GridCoarseLevels, AGridOfCubesCoarsensToTheTwoHGrid) {
  const PolyhedralMesh mesh = polyhedral_mesh_from_volume_mesh(structured_grid(
      Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(1.6, 0.8, 0.8)), {16, 8, 8}, ElementType::hex8));
  std::vector<DgFace> faces = mesh_faces(mesh);
  const DgLinearSystem system(mesh_cells(mesh), faces, {1, Flux::interior_penalty, 20, 1, 1});
  const VertexCoarseSpace space = vertex_coarse_space(mesh, system);
  const std::vector<Eigen::SparseMatrix<double>> levels = grid_coarse_levels(mesh, system, space);
  // 17 × 9 × 9 = 1377 vertices > 512: the 2h grid (9 × 5 × 5 = 225 nodes) is the coarsest.
  ASSERT_EQ(levels.size(), 1u);
  EXPECT_EQ(levels[0].rows(), 3 * 17 * 9 * 9);
  EXPECT_EQ(levels[0].cols(), 3 * 9 * 5 * 5);
  // Nested: a vertex on the 2h grid takes its node's value alone (one entry of weight 1 per
  // component), the others 2, 4 or 8 entries.
  int nested = 0;
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = levels[0];
  for (Eigen::Index row = 0; row < rows.rows(); row += 3)
    if (rows.outerIndexPtr()[row + 1] - rows.outerIndexPtr()[row] == 1) {
      EXPECT_EQ(rows.valuePtr()[rows.outerIndexPtr()[row]], 1.0);
      ++nested;
    }
  EXPECT_EQ(nested, 9 * 5 * 5);
}

TEST(GridCoarseLevels, NoLevelWhenThePointsAreAlreadyFew) {
  EXPECT_TRUE(grid_coarse_levels(scattered_points(), 0.2, 100000).empty());
}

}  // namespace
}  // namespace altfem::dg
