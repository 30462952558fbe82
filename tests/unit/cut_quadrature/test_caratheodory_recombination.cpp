// Carathéodory–Steinitz recombination (shared/quadrature/caratheodory_recombination.hpp):
// the weighted column sum is kept, the weights stay non-negative on a subset, and the
// support shrinks to the target size or the columns' rank, whichever is larger.
#include <gtest/gtest.h>

#include <random>

#include "shared/quadrature/caratheodory_recombination.hpp"

namespace altfem {
namespace {

struct RandomMeasure {
  Eigen::MatrixXd columns;  // rows × count
  Eigen::VectorXd weights;  // count, > 0
};

/// Columns with a constant first row (so the total weight is one of the kept sums),
/// the others random; `rank` independent rows, the rest their combinations.
RandomMeasure random_measure(int rows, int rank, int count, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  RandomMeasure measure;
  Eigen::MatrixXd independent(rank, count);
  for (int j = 0; j < count; ++j) {
    independent(0, j) = 1.0;
    for (int i = 1; i < rank; ++i) independent(i, j) = unit(generator);
  }
  Eigen::MatrixXd mixing = Eigen::MatrixXd::Identity(rows, rank);
  for (int i = rank; i < rows; ++i)
    for (int k = 0; k < rank; ++k) mixing(i, k) = unit(generator);
  measure.columns = mixing * independent;
  measure.weights.resize(count);
  for (int j = 0; j < count; ++j) measure.weights(j) = 0.5 + 0.5 * unit(generator);
  return measure;
}

void expect_recombined(const RandomMeasure& measure, const Eigen::VectorXd& result, Eigen::Index most) {
  ASSERT_EQ(result.size(), measure.weights.size());
  EXPECT_TRUE((result.array() >= 0.0).all());
  EXPECT_LE((result.array() > 0.0).count(), most);
  const Eigen::VectorXd before = measure.columns * measure.weights, after = measure.columns * result;
  EXPECT_LE((after - before).cwiseAbs().maxCoeff(), 1e-13 * measure.weights.sum());
}

TEST(CaratheodoryRecombination, KeepsTheSumOnAtMostRankPoints) {
  for (unsigned seed = 0; seed < 20; ++seed) {
    const RandomMeasure measure = random_measure(20, 20, 3000 + 37 * static_cast<int>(seed), seed);
    expect_recombined(measure, caratheodory_recombination(measure.columns, measure.weights, 20), 20);
  }
}

TEST(CaratheodoryRecombination, RankDeficientColumnsReduceToTheRank) {
  const RandomMeasure measure = random_measure(35, 24, 2000, 7);
  expect_recombined(measure, caratheodory_recombination(measure.columns, measure.weights, 1), 24);
}

TEST(CaratheodoryRecombination, StopsAtTheTargetSize) {
  // Halving rounds: the result has at most the target, but more than half of it.
  const RandomMeasure measure = random_measure(10, 10, 5000, 3);
  const Eigen::VectorXd result = caratheodory_recombination(measure.columns, measure.weights, 400);
  expect_recombined(measure, result, 400);
  EXPECT_GT((result.array() > 0.0).count(), 200);
}

TEST(CaratheodoryRecombination, ZeroWeightsStayZeroAndSmallInputsAreKept) {
  RandomMeasure measure = random_measure(6, 6, 200, 11);
  measure.weights.head(100).setZero();
  const Eigen::VectorXd result = caratheodory_recombination(measure.columns, measure.weights, 6);
  EXPECT_TRUE((result.head(100).array() == 0.0).all());
  expect_recombined(measure, result, 6);
  const RandomMeasure small = random_measure(6, 6, 5, 12);
  const Eigen::VectorXd same = caratheodory_recombination(small.columns, small.weights, 6);
  EXPECT_EQ(same, small.weights);
}

}  // namespace
}  // namespace altfem
