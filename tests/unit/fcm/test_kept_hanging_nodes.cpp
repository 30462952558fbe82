// kept_hanging_nodes (shared/cut_cells/kept_hanging_nodes.hpp) on hand-made inputs: a grid
// with free nodes 0 and 1 and one hanging node (grid node 2) halfway between them, on the
// face of the coarse leaf 0; a finer leaf 1 holds the hanging node. With topology-aware
// cells a grid node has a copy per part of the material around it, so the coarse leaf can
// hold two pieces, each with its own copies of nodes 0 and 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/cut_cells/kept_hanging_nodes.hpp"

namespace altfem {
namespace {

const HangingNodeSources sources{{HangingNodeSource{0, {0, 1}, {0.5, 0.5}}}};
constexpr int grid_free_nodes = 2;

// The kept node's constraint after renumbering: its masters as kept nodes, with weights.
std::vector<std::pair<int, double>> constraint_of(const KeptHangingNodes& kept, int node) {
  const int hanging = kept.new_index[node] - kept.constraints.free_nodes;
  EXPECT_GE(hanging, 0);
  std::vector<int> kept_of(kept.new_index.size());
  for (std::size_t k = 0; k < kept.new_index.size(); ++k) kept_of[kept.new_index[k]] = static_cast<int>(k);
  std::vector<std::pair<int, double>> result;
  for (std::size_t m = 0; m < kept.constraints.masters[hanging].size(); ++m)
    result.emplace_back(kept_of[kept.constraints.masters[hanging][m]], kept.constraints.weights[hanging][m]);
  std::sort(result.begin(), result.end());
  return result;
}

// Kept nodes: 0, 1 (piece A's copies of grid nodes 0, 1), 2, 3 (piece B's), 4 (the hanging
// node's copy). Cells (2 nodes each, enough for the logic): A = (0, 1) and B = (2, 3) in
// leaf 0; the fine cell in leaf 1 holds the hanging copy and `fine_partner`.
KeptHangingNodes two_pieces(int fine_partner) {
  const std::vector<int> background_node{0, 1, 0, 1, 2};
  Eigen::MatrixXi cells(3, 2);
  cells << 0, 1, 2, 3, 4, fine_partner;
  return kept_hanging_nodes(background_node, grid_free_nodes, sources, cells, {0, 0, 1});
}

TEST(KeptHangingNodes, AHangingNodeTakesTheCopiesOfThePieceItsCellsMeet) {
  // The fine cell shares piece B's copy of grid node 1: the material continues into B.
  const KeptHangingNodes kept = two_pieces(3);
  EXPECT_EQ(kept.constraints.hanging_nodes(), 1);
  const std::vector<std::pair<int, double>> expected{{2, 0.5}, {3, 0.5}};
  EXPECT_EQ(constraint_of(kept, 4), expected);
}

TEST(KeptHangingNodes, APieceOfItsOwnGivesItsCopies) {
  const std::vector<int> background_node{0, 1, 2};
  Eigen::MatrixXi cells(2, 2);
  cells << 0, 1, 2, 2;
  const KeptHangingNodes kept = kept_hanging_nodes(background_node, grid_free_nodes, sources, cells, {0, 1});
  const std::vector<std::pair<int, double>> expected{{0, 0.5}, {1, 0.5}};
  EXPECT_EQ(constraint_of(kept, 2), expected);
}

TEST(KeptHangingNodes, NoPieceOrBothPiecesMeetingItIsANumericalFailure) {
  // Sharing no node with either piece, or (through a third cell) with both, the hanging
  // node's continuation is not decided.
  EXPECT_THROW(two_pieces(4), NumericalError);
  const std::vector<int> background_node{0, 1, 0, 1, 2};
  Eigen::MatrixXi cells(4, 2);
  cells << 0, 1, 2, 3, 4, 1, 4, 3;
  EXPECT_THROW(kept_hanging_nodes(background_node, grid_free_nodes, sources, cells, {0, 0, 1, 1}), NumericalError);
}

TEST(KeptHangingNodes, ANodeOnNoKeptLeafIsFree) {
  // Its only leaf (0) holds no kept cell: nothing to conform to.
  const std::vector<int> background_node{2};
  Eigen::MatrixXi cells(1, 2);
  cells << 0, 0;
  const KeptHangingNodes kept = kept_hanging_nodes(background_node, grid_free_nodes, sources, cells, {1});
  EXPECT_EQ(kept.constraints.hanging_nodes(), 0);
}

}  // namespace
}  // namespace altfem
