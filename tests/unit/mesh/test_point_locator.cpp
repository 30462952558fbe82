// PointLocator (issue #14, item 5): its candidates are every box (enlarged by the
// slack) that holds the point, checked against brute force over random boxes of
// mixed sizes, in element order without repeats.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "shared/mesh/point_locator.hpp"

namespace altfem {
namespace {

TEST(PointLocator, CandidatesAreExactlyTheBoxesHoldingThePoint) {
  std::mt19937 random(21);
  std::uniform_real_distribution<double> position(-2.0, 3.0), size(0.01, 0.6);
  std::vector<Eigen::AlignedBox3d> boxes;
  for (int e = 0; e < 400; ++e) {
    const Eigen::Vector3d corner(position(random), position(random), position(random));
    // A few long boxes, spanning many buckets.
    const double scale = e % 50 == 0 ? 6.0 : 1.0;
    boxes.emplace_back(corner, corner + scale * Eigen::Vector3d(size(random), size(random), size(random)));
  }
  const PointLocator locator(boxes);
  ASSERT_EQ(locator.size(), 400);
  std::vector<int> candidates;
  int found = 0;
  for (int p = 0; p < 2000; ++p) {
    // Some points outside every bucket's range, some on box corners.
    const Eigen::Vector3d x = p % 100 == 0
                                  ? boxes[p / 100].max()
                                  : Eigen::Vector3d(1.3 * position(random), position(random), position(random));
    for (const double slack : {0.0, 0.05}) {
      std::vector<int> expected;
      for (int e = 0; e < 400; ++e) {
        Eigen::AlignedBox3d enlarged = boxes[e];
        enlarged.min().array() -= slack;
        enlarged.max().array() += slack;
        if (enlarged.contains(x)) expected.push_back(e);
      }
      locator.candidates(x, slack, candidates);
      EXPECT_EQ(candidates, expected) << "point " << x.transpose() << " slack " << slack;
      found += static_cast<int>(expected.size());
    }
  }
  EXPECT_GT(found, 500);  // the comparison saw many hits, not only empty lists
  EXPECT_EQ(locator.box(7).min(), boxes[7].min());
}

TEST(PointLocator, SingleAndDegenerateBoxes) {
  // One flat box (zero thickness in z): the bucket spacing must stay positive.
  const PointLocator locator({Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 1, 1))});
  std::vector<int> candidates{5, 6};
  locator.candidates(Eigen::Vector3d(0.5, 0.5, 1.0), 0.0, candidates);
  EXPECT_EQ(candidates, std::vector<int>{0});
  locator.candidates(Eigen::Vector3d(0.5, 0.5, 1.1), 0.0, candidates);
  EXPECT_TRUE(candidates.empty());
  locator.candidates(Eigen::Vector3d(0.5, 0.5, 1.1), 0.2, candidates);
  EXPECT_EQ(candidates, std::vector<int>{0});
}

}  // namespace
}  // namespace altfem
