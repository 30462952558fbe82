#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <random>
#include <vector>

#include "shared/mesh/spatial_order.hpp"
#include "shared/mesh/structured_grid.hpp"

namespace altfem {
namespace {

// The grid with cells and nodes in random order, plus one node that no cell uses:
// what a mesher that numbers in creation order hands over.
VolumeMesh shuffled_grid() {
  const VolumeMesh grid = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                                          Eigen::Vector3i(10, 10, 10), ElementType::tet4);
  std::mt19937 random(5);
  std::vector<int> node_order(static_cast<std::size_t>(grid.nodes.rows()));
  std::iota(node_order.begin(), node_order.end(), 0);
  std::shuffle(node_order.begin(), node_order.end(), random);
  std::vector<int> cell_order(static_cast<std::size_t>(grid.cells.rows()));
  std::iota(cell_order.begin(), cell_order.end(), 0);
  std::shuffle(cell_order.begin(), cell_order.end(), random);

  VolumeMesh shuffled;
  shuffled.element_type = grid.element_type;
  shuffled.nodes.resize(grid.nodes.rows() + 1, 3);
  for (Eigen::Index node = 0; node < grid.nodes.rows(); ++node)
    shuffled.nodes.row(node_order[static_cast<std::size_t>(node)]) = grid.nodes.row(node);
  shuffled.nodes.row(grid.nodes.rows()) << 5, 5, 5;  // unused
  shuffled.cells.resize(grid.cells.rows(), grid.cells.cols());
  for (Eigen::Index cell = 0; cell < grid.cells.rows(); ++cell)
    for (Eigen::Index k = 0; k < grid.cells.cols(); ++k)
      shuffled.cells(cell_order[static_cast<std::size_t>(cell)], k) =
          node_order[static_cast<std::size_t>(grid.cells(cell, k))];
  return shuffled;
}

// Each cell as the coordinates of its nodes in its own node order, sorted over cells.
std::vector<std::array<double, 12>> cells_by_coordinates(const VolumeMesh& mesh) {
  std::vector<std::array<double, 12>> cells;
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell) {
    std::array<double, 12> corners{};
    for (int k = 0; k < 4; ++k)
      for (int d = 0; d < 3; ++d) corners[static_cast<std::size_t>(3 * k + d)] = mesh.nodes(mesh.cells(cell, k), d);
    cells.push_back(corners);
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

// Mean over cells of the spread of their node indices: small when neighbours in
// space are neighbours in memory.
double mean_index_spread(const VolumeMesh& mesh) {
  double sum = 0;
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    sum += mesh.cells.row(cell).maxCoeff() - mesh.cells.row(cell).minCoeff();
  return sum / static_cast<double>(mesh.cells.rows());
}

TEST(SpatialOrder, SameCellsSameNodesOnlyRenumbered) {
  const VolumeMesh shuffled = shuffled_grid();
  const VolumeMesh ordered = spatially_ordered(shuffled);
  EXPECT_EQ(ordered.element_type, shuffled.element_type);
  ASSERT_EQ(ordered.nodes.rows(), shuffled.nodes.rows());
  ASSERT_EQ(ordered.cells.rows(), shuffled.cells.rows());
  EXPECT_EQ(cells_by_coordinates(ordered), cells_by_coordinates(shuffled));
  // The unused node keeps its place after all used ones.
  EXPECT_EQ(ordered.nodes.row(ordered.nodes.rows() - 1), Eigen::RowVector3d(5, 5, 5));
}

TEST(SpatialOrder, NeighboursInSpaceBecomeNeighboursInMemory) {
  const VolumeMesh shuffled = shuffled_grid();
  const VolumeMesh ordered = spatially_ordered(shuffled);
  const double before = mean_index_spread(shuffled), after = mean_index_spread(ordered);
  // Random order: about half the 1331 nodes apart. Along the Hilbert curve a cell's
  // nodes are a few grid layers apart at most (measured: 795 -> 133).
  EXPECT_GT(before, 500.0);
  EXPECT_LT(after, 0.25 * before) << "spread " << before << " -> " << after;
  // Cells follow one another in space: consecutive centroids are close on average.
  double step = 0;
  for (Eigen::Index cell = 1; cell < ordered.cells.rows(); ++cell) {
    Eigen::Vector3d previous = Eigen::Vector3d::Zero(), current = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) {
      previous += ordered.nodes.row(ordered.cells(cell - 1, k)).transpose() / 4;
      current += ordered.nodes.row(ordered.cells(cell, k)).transpose() / 4;
    }
    step += (current - previous).norm();
  }
  EXPECT_LT(step / static_cast<double>(ordered.cells.rows() - 1), 0.1);  // grid spacing 0.1; random order ~0.6
}

}  // namespace
}  // namespace altfem
