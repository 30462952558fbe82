// Bulk marking (Dörfler 1996) of a refine event with `fraction` (refine_marking.hpp): the
// fewest cells, largest estimates first, whose squared estimates carry the fraction of their
// sum. Five cells in a row along x with uniaxial stresses σ_xx = 1, 2, 3, 4, 5 Pa and unit
// volumes: principal_stress's estimates |K| σ₁² are 1, 4, 9, 16, 25 (sum 55).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "shared/fem/refine_marking.hpp"

namespace altfem {
namespace {

struct Row {
  std::vector<Eigen::Matrix3d> stresses;
  Eigen::MatrixXd centroids = Eigen::MatrixXd::Zero(5, 3);
  Eigen::VectorXd volumes = Eigen::VectorXd::Ones(5);
  IndicatorFaces faces;
  Row() {
    for (int cell = 0; cell < 5; ++cell) {
      Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();
      stress(0, 0) = cell + 1.0;
      stresses.push_back(stress);
      centroids(cell, 0) = cell + 0.5;
      if (cell > 0) faces.interior.push_back({cell - 1, cell, 1.0, Eigen::Vector3d::UnitX()});
    }
  }
  std::vector<int> marked(const RefineSpec& refine, const std::vector<int>& levels = {}) const {
    nlohmann::json facts;
    return mark_cells_to_refine(refine, stresses, faces, centroids, volumes, levels, 1e-12, facts).cells;
  }
};

TEST(BulkMarking, TakesTheFewestLargestEstimatesThatCarryTheFraction) {
  const Row row;
  RefineSpec refine;
  refine.fraction = 25.0 / 55.0;  // the largest alone
  EXPECT_EQ(row.marked(refine), (std::vector<int>{4}));
  refine.fraction = 0.5;  // 25 + 16 = 41 ≥ 27.5 > 25
  EXPECT_EQ(row.marked(refine), (std::vector<int>{3, 4}));
  refine.fraction = 1.0;
  EXPECT_EQ(row.marked(refine), (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(BulkMarking, ScalesByTheCellsVolume) {
  Row row;
  row.volumes[0] = 100;  // 100 · 1² = 100 outweighs 25
  RefineSpec refine;
  refine.fraction = 0.5;
  EXPECT_EQ(row.marked(refine), (std::vector<int>{0}));
}

// The traction jumps (σ_K − σ_N) n across the four faces are 1 Pa each: the end cells carry
// one face's, the inner cells two, so η² = h Σ_F |F| |jump|² is 1, 2, 2, 2, 1 (sum 8), and a
// half takes two inner cells, the first of equal estimates first.
TEST(BulkMarking, WeighsTheTractionJumpsByTheCellsSize) {
  const Row row;
  RefineSpec refine;
  refine.criterion = RefineCriterion::error_indicator;
  refine.fraction = 0.5;
  EXPECT_EQ(row.marked(refine), (std::vector<int>{1, 2}));
}

TEST(BulkMarking, MarkedCellsAtMaxLevelAndOutsideTheRegionAreLeftOut) {
  const Row row;
  RefineSpec refine;
  refine.fraction = 0.5;
  refine.max_level = 1;
  EXPECT_EQ(row.marked(refine, {0, 0, 0, 0, 1}), (std::vector<int>{3}));
  RegionSelector first_three;
  first_three.box = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(3, 1, 1));
  refine.region = first_three;
  EXPECT_EQ(row.marked(refine, {}), (std::vector<int>{2}));  // of 1, 4, 9: 9 ≥ 7
}

// The boundary residual σ_K n − t (Kelly et al. 1983's Neumann term): the row under a
// uniform σ_xx = 2 Pa has no jumps; its end faces x = 0 and x = 5 loaded by the traction
// that balances it leave nothing to mark, and left free (t = 0) each end cell's residual is
// σn, 2 Pa on a face of area 1 beside an interior face without a jump: √((1·4 + 1·0)/2).
TEST(TractionJumpIndicator, ABoundaryFaceWeighsItsResidualAgainstTheLoad) {
  Row row;
  for (Eigen::Matrix3d& stress : row.stresses) stress(0, 0) = 2;
  const Eigen::Vector3d out_of_first = -Eigen::Vector3d::UnitX(), out_of_last = Eigen::Vector3d::UnitX();
  row.faces.boundary = {{0, 1.0, out_of_first, 2 * out_of_first}, {4, 1.0, out_of_last, 2 * out_of_last}};
  EXPECT_EQ(traction_jump_indicator(5, row.faces, row.stresses), Eigen::VectorXd::Zero(5));
  for (LoadedBoundaryFace& face : row.faces.boundary) face.traction.setZero();
  const Eigen::VectorXd free_ends = traction_jump_indicator(5, row.faces, row.stresses);
  EXPECT_EQ(free_ends, (Eigen::VectorXd(5) << std::sqrt(2.0), 0, 0, 0, std::sqrt(2.0)).finished());
  RefineSpec refine;
  refine.criterion = RefineCriterion::error_indicator;
  refine.threshold = 1.4;
  EXPECT_EQ(row.marked(refine), (std::vector<int>{0, 4}));
}

}  // namespace
}  // namespace altfem
