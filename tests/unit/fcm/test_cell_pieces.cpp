// Topology-aware cells (shared/cut_cells/cell_pieces.hpp, shared/cut_cells/piece_mesh.hpp): the connected pieces
// of the material in each background cell, exact piece volumes, and one node copy per
// connected part of the material around the node.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>

#include "shared/cut_cells/cell_pieces.hpp"
#include "shared/cut_cells/cell_rules.hpp"
#include "shared/cut_cells/cut_cell_rule.hpp"
#include "shared/cut_cells/piece_basis_evaluator.hpp"
#include "shared/cut_cells/piece_mesh.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/mesh/weld_coincident_nodes.hpp"

namespace altfem::fcm {
namespace {

VolumeMesh box_tetrahedra(const Eigen::Vector3d& low, const Eigen::Vector3d& high, const Eigen::Vector3i& resolution) {
  return structured_grid(Eigen::AlignedBox3d(low, high), resolution, ElementType::tet4);
}

// Both meshes in one (their nodes kept apart: the parts touch nowhere).
VolumeMesh concatenate(const VolumeMesh& first, const VolumeMesh& second) {
  VolumeMesh mesh{ElementType::tet4, Eigen::MatrixXd(first.nodes.rows() + second.nodes.rows(), 3),
                  Eigen::MatrixXi(first.cells.rows() + second.cells.rows(), 4)};
  mesh.nodes << first.nodes, second.nodes;
  mesh.cells << first.cells, (second.cells.array() + static_cast<int>(first.nodes.rows())).matrix();
  return mesh;
}

// The mesh without the cells whose centroid `remove` holds (nodes kept: unused ones are harmless).
VolumeMesh without_cells(const VolumeMesh& mesh, const std::function<bool(const Eigen::Vector3d&)>& remove) {
  VolumeMesh result{mesh.element_type, mesh.nodes, Eigen::MatrixXi(0, mesh.cells.cols())};
  std::vector<Eigen::Index> kept;
  for (Eigen::Index c = 0; c < mesh.cells.rows(); ++c) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (Eigen::Index a = 0; a < 4; ++a) centroid += mesh.nodes.row(mesh.cells(c, a)).transpose() / 4;
    if (!remove(centroid)) kept.push_back(c);
  }
  result.cells.resize(static_cast<Eigen::Index>(kept.size()), mesh.cells.cols());
  for (std::size_t k = 0; k < kept.size(); ++k)
    result.cells.row(static_cast<Eigen::Index>(k)) = mesh.cells.row(kept[k]);
  return result;
}

// The physical volume of a piece: its tetrahedra clipped by the cell.
double piece_volume(const VolumeMesh& background, int cell, const std::vector<int>& tetrahedra,
                    const VolumeMesh& embedded) {
  const int corners = element_corner_count(background.element_type);
  Eigen::MatrixXd cell_corners(corners, 3);
  for (int i = 0; i < corners; ++i) cell_corners.row(i) = background.nodes.row(background.cells(cell, i));
  std::vector<TetrahedronCorners> pieces;
  for (const int t : tetrahedra) {
    TetrahedronCorners tetrahedron;
    for (int i = 0; i < 4; ++i) tetrahedron.row(i) = embedded.nodes.row(embedded.cells(t, i));
    pieces.push_back(tetrahedron);
  }
  return intersection_rule(CellGeometry(background.element_type, cell_corners), pieces, 1).clipped_volume;
}

std::set<int> nodes_of(const PieceMesh& mesh, int row) {
  std::set<int> nodes;
  for (Eigen::Index a = 0; a < mesh.mesh.cells.cols(); ++a) nodes.insert(mesh.mesh.cells(row, a));
  return nodes;
}

int shared_nodes(const PieceMesh& mesh, int first, int second) {
  const std::set<int> a = nodes_of(mesh, first), b = nodes_of(mesh, second);
  return static_cast<int>(std::count_if(a.begin(), a.end(), [&](int node) { return b.count(node) > 0; }));
}

// Two bars 0.2 apart, x in [0.5, 2], in a row of two cells [0, 1] and [1, 2]. With two
// embedded cells along x the tetrahedra cross the cell face x = 1 (the same tetrahedron
// connects both sides); with three they end on it (face-neighbours in the face connect).
class TwoBars : public ::testing::TestWithParam<int> {};

TEST_P(TwoBars, EachCellHoldsTwoPiecesAndEveryNodeTwoCopies) {
  const Eigen::Vector3i resolution(GetParam(), 1, 2);
  const VolumeMesh embedded = concatenate(box_tetrahedra({0.5, 0, 0}, {2, 0.4, 1}, resolution),
                                          box_tetrahedra({0.5, 0.6, 0}, {2, 1, 1}, resolution));
  const VolumeMesh background = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1)),
                                                Eigen::Vector3i(2, 1, 1), ElementType::hex8);
  const CellPieces pieces = find_cell_pieces(background, embedded);
  EXPECT_EQ(pieces.split_cells(), 2);
  ASSERT_EQ(pieces.piece_count(), 4);
  const double cell_volume[2] = {0.5 * 0.4, 0.4};
  for (int cell = 0; cell < 2; ++cell)
    for (int piece = 0; piece < 2; ++piece)
      EXPECT_NEAR(piece_volume(background, cell, pieces.tetrahedra[cell][piece], embedded), cell_volume[cell], 1e-14);
  // The lower bar's piece continues into the lower bar's piece of the next cell, only.
  const int lower_count = 6 * resolution.prod();  // the lower bar's tetrahedra come first
  for (int piece = 0; piece < 2; ++piece) {
    const bool is_lower = pieces.tetrahedra[0][piece].front() < lower_count;
    const int partner = (pieces.tetrahedra[1][0].front() < lower_count) == is_lower ? 0 : 1;
    EXPECT_EQ(pieces.neighbours[0][piece], (std::vector<PieceReference>{{1, partner}}));
  }

  const PieceMesh mesh = piece_mesh(background, pieces);
  ASSERT_EQ(mesh.mesh.cells.rows(), 4);
  EXPECT_EQ(mesh.mesh.nodes.rows(), 24);   // 12 grid nodes, two copies each
  EXPECT_EQ(shared_nodes(mesh, 0, 1), 0);  // the two pieces of a cell share no DOF
  int across = 0;                          // the four face nodes, per bar
  for (int piece = 0; piece < 2; ++piece)
    for (int other = 2; other < 4; ++other) across += shared_nodes(mesh, piece, other);
  EXPECT_EQ(across, 8);
}

INSTANTIATE_TEST_SUITE_P(EmbeddedCellsAlongTheBars, TwoBars, ::testing::Values(2, 3));

// Every tetrahedron with nodes of its own (a soup, as some mesh files are): welded, its
// pieces are those of the shared-node mesh; unwelded, every tetrahedron is a piece.
TEST(CellPieces, ASoupWeldedHasThePiecesOfTheSharedNodeMesh) {
  const VolumeMesh shared = box_tetrahedra({0.5, 0, 0}, {2, 0.4, 1}, Eigen::Vector3i(3, 1, 2));
  VolumeMesh soup{ElementType::tet4, Eigen::MatrixXd(4 * shared.cells.rows(), 3),
                  Eigen::MatrixXi(shared.cells.rows(), 4)};
  for (int t = 0; t < shared.cells.rows(); ++t)
    for (int a = 0; a < 4; ++a) {
      soup.nodes.row(4 * t + a) = shared.nodes.row(shared.cells(t, a));
      soup.cells(t, a) = 4 * t + a;
    }
  const VolumeMesh background = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1)),
                                                Eigen::Vector3i(2, 1, 1), ElementType::hex8);
  const VolumeMesh welded = weld_coincident_nodes(soup);
  EXPECT_EQ(welded.nodes.rows(), shared.nodes.rows());
  const CellPieces pieces = find_cell_pieces(background, welded);
  EXPECT_EQ(pieces.piece_count(), 2);
  EXPECT_EQ(pieces.tetrahedra, find_cell_pieces(background, shared).tetrahedra);
  EXPECT_EQ(pieces.neighbours[0][0], (std::vector<PieceReference>{{1, 0}}));
  EXPECT_GT(find_cell_pieces(background, soup).piece_count(), 2);
}

// A box touching its cell's face from inside leaves the neighbour without material.
TEST(CellPieces, PieceTouchingAFaceLeavesTheNeighbourEmpty) {
  const VolumeMesh embedded = box_tetrahedra({0.2, 0.2, 0.2}, {1, 0.8, 0.8}, Eigen::Vector3i(2, 2, 2));
  const VolumeMesh background = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1)),
                                                Eigen::Vector3i(2, 1, 1), ElementType::hex8);
  const CellPieces pieces = find_cell_pieces(background, embedded);
  ASSERT_EQ(pieces.tetrahedra[0].size(), 1u);
  EXPECT_TRUE(pieces.tetrahedra[1].empty());
  EXPECT_TRUE(pieces.neighbours[0][0].empty());
  EXPECT_NEAR(piece_volume(background, 0, pieces.tetrahedra[0][0], embedded), 0.8 * 0.6 * 0.6, 1e-14);
  const PieceMesh mesh = piece_mesh(background, pieces);
  EXPECT_EQ(mesh.mesh.cells.rows(), 2);
  EXPECT_EQ(mesh.mesh.nodes.rows(), 12);
  EXPECT_TRUE(mesh.tetrahedra[1].empty());
}

// The same block with its face nodes on x = 1 moved 1e-13 past it (a cut's new nodes,
// rounded off the cell's face): the neighbour's clips of rounding volume (a few 1e-13 of
// their tetrahedra's) make it no piece, whose functions would hold no mass; what is past
// the face, 1e-13 of the block's volume, is lost.
TEST(CellPieces, APieceRoundedPastAFaceLeavesTheNeighbourEmpty) {
  VolumeMesh embedded = box_tetrahedra({0.2, 0.2, 0.2}, {1, 0.8, 0.8}, Eigen::Vector3i(2, 2, 2));
  for (Eigen::Index node = 0; node < embedded.nodes.rows(); ++node)
    if (embedded.nodes(node, 0) == 1) embedded.nodes(node, 0) = 1 + 1e-13;
  const VolumeMesh background = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1)),
                                                Eigen::Vector3i(2, 1, 1), ElementType::hex8);
  const CellPieces pieces = find_cell_pieces(background, embedded);
  ASSERT_EQ(pieces.tetrahedra[0].size(), 1u);
  EXPECT_TRUE(pieces.tetrahedra[1].empty());
  EXPECT_NEAR(piece_volume(background, 0, pieces.tetrahedra[0][0], embedded), 0.8 * 0.6 * 0.6, 1e-13);
}

// A U: two legs x in [0, 0.3] and [0.7, 1] rising from y = 0 to y = 1.5, joined by a bar
// y in [1.2, 1.5]. The lower cell (y in [0, 1]) holds the legs apart; the upper cell
// holds the bend. The legs' pieces share the nodes of the face y = 1 (the material joins
// through the upper cell) and have their own copies of the nodes at y = 0.
TEST(CellPieces, UShapeJoinsThroughTheNeighbouringCell) {
  const VolumeMesh embedded =
      without_cells(box_tetrahedra({0, 0, 0}, {1, 1.5, 1}, Eigen::Vector3i(10, 15, 1)),
                    [](const Eigen::Vector3d& x) { return x.x() > 0.3 && x.x() < 0.7 && x.y() < 1.2; });
  const VolumeMesh background = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 2, 1)),
                                                Eigen::Vector3i(1, 2, 1), ElementType::hex8);
  const CellPieces pieces = find_cell_pieces(background, embedded);
  ASSERT_EQ(pieces.tetrahedra[0].size(), 2u);
  ASSERT_EQ(pieces.tetrahedra[1].size(), 1u);
  EXPECT_EQ(pieces.split_cells(), 1);
  for (int piece = 0; piece < 2; ++piece) {
    EXPECT_NEAR(piece_volume(background, 0, pieces.tetrahedra[0][piece], embedded), 0.3, 1e-14);
    EXPECT_EQ(pieces.neighbours[0][piece], (std::vector<PieceReference>{{1, 0}}));
  }
  EXPECT_NEAR(piece_volume(background, 1, pieces.tetrahedra[1][0], embedded), 2 * 0.3 * 0.2 + 0.3, 1e-14);

  const PieceMesh mesh = piece_mesh(background, pieces);
  ASSERT_EQ(mesh.mesh.cells.rows(), 3);
  EXPECT_EQ(mesh.mesh.nodes.rows(), 4 * 2 + 4 + 4);  // y = 0 twice; y = 1 and y = 2 once
  EXPECT_EQ(shared_nodes(mesh, 0, 1), 4);            // the face y = 1
  EXPECT_EQ(shared_nodes(mesh, 0, 2), 4);
  EXPECT_EQ(shared_nodes(mesh, 1, 2), 4);
}

// A rebuild after an event takes the clips of the tetrahedra it left alone from the build
// before (ClippedTetrahedronMemory): the pieces are those found from scratch, whether the
// event removed material (the U's right leg shortened) or left it all.
TEST(CellPieces, ClipsKeptFromTheBuildBeforeGiveThePiecesFoundFromScratch) {
  const VolumeMesh background = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 2, 1)),
                                                Eigen::Vector3i(1, 2, 1), ElementType::hex8);
  const VolumeMesh u_shape =
      without_cells(box_tetrahedra({0, 0, 0}, {1, 1.5, 1}, Eigen::Vector3i(10, 15, 1)),
                    [](const Eigen::Vector3d& x) { return x.x() > 0.3 && x.x() < 0.7 && x.y() < 1.2; });
  ClippedTetrahedronMemory before;
  find_cell_pieces(background, u_shape, nullptr, nullptr, &before);
  EXPECT_GT(before.size(), 0u);
  const VolumeMesh shorter =
      without_cells(u_shape, [](const Eigen::Vector3d& x) { return x.x() > 0.7 && x.y() < 0.4; });
  for (const VolumeMesh* embedded : {&u_shape, &shorter}) {
    const CellPieces fresh = find_cell_pieces(background, *embedded);
    ClippedTetrahedronMemory after;
    const CellPieces kept = find_cell_pieces(background, *embedded, nullptr, &before, &after);
    EXPECT_EQ(kept.tetrahedra, fresh.tetrahedra);
    EXPECT_EQ(kept.neighbours, fresh.neighbours);
    EXPECT_EQ(kept.filled, fresh.filled);
    EXPECT_LE(after.size(), before.size());  // this build's clips only
  }
}

// The same two bars in a tetrahedral background (each grid cube split into 6).
TEST(CellPieces, TetrahedralCellsSplitToo) {
  const VolumeMesh embedded = concatenate(box_tetrahedra({0, 0, 0}, {1, 0.4, 1}, Eigen::Vector3i(2, 1, 2)),
                                          box_tetrahedra({0, 0.6, 0}, {1, 1, 1}, Eigen::Vector3i(2, 1, 2)));
  const VolumeMesh background = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                                                Eigen::Vector3i(1, 1, 1), ElementType::tet4);
  const CellPieces pieces = find_cell_pieces(background, embedded);
  double volume = 0;
  for (int cell = 0; cell < 6; ++cell)
    for (const auto& piece : pieces.tetrahedra[cell]) volume += piece_volume(background, cell, piece, embedded);
  EXPECT_NEAR(volume, 0.8, 1e-14);
  EXPECT_GT(pieces.split_cells(), 0);
  // No node copy is shared by a piece of each bar: the bars never meet.
  const PieceMesh mesh = piece_mesh(background, pieces);
  for (int a = 0; a < mesh.mesh.cells.rows(); ++a)
    for (int b = 0; b < mesh.mesh.cells.rows(); ++b) {
      if (mesh.tetrahedra[a].empty() || mesh.tetrahedra[b].empty()) continue;
      const bool a_lower = mesh.tetrahedra[a].front() < 24, b_lower = mesh.tetrahedra[b].front() < 24;
      if (a_lower != b_lower) {
        EXPECT_EQ(shared_nodes(mesh, a, b), 0) << a << " " << b;
      }
    }
}

// Surface points go to the nearest piece: the distance to a tetrahedron is 0 inside and
// on it (within 1e-12), the distance to the nearest face, edge or corner outside.
TEST(PieceBasisEvaluator, DistanceToATetrahedronIsExact) {
  TetrahedronCorners unit;
  unit << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  EXPECT_EQ(distance_to_tetrahedron({0.1, 0.2, 0.3}, unit), 0.0);
  EXPECT_EQ(distance_to_tetrahedron({0.5, 0.5, 0.0}, unit), 0.0);
  EXPECT_EQ(distance_to_tetrahedron({0.2, 0.3, -1e-14}, unit), 0.0);  // a rounding off a face is on it
  EXPECT_NEAR(distance_to_tetrahedron({0.2, 0.3, -1e-9}, unit), 1e-9, 1e-15);
  // Asked only whether it holds the point: the least positive double for one outside.
  const double least = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(distance_to_tetrahedron({0.2, 0.3, -0.25}, unit, least), least);
  EXPECT_EQ(distance_to_tetrahedron({0.2, 0.3, 0.25}, unit, least), 0.0);
  EXPECT_NEAR(distance_to_tetrahedron({0.2, 0.3, -0.25}, unit), 0.25, 1e-15);  // below a face
  EXPECT_NEAR(distance_to_tetrahedron({1, 1, 1}, unit), (Eigen::Vector3d(1, 1, 1) / 3 * 2).norm(),
              1e-15);                                                                // off the slanted face
  EXPECT_NEAR(distance_to_tetrahedron({-1, -1, 0.5}, unit), std::sqrt(2.0), 1e-15);  // off the z edge
  EXPECT_NEAR(distance_to_tetrahedron({2, -1, -1}, unit), std::sqrt(3.0), 1e-15);    // off corner (1, 0, 0)
}

// Two bars in each of two cells, the lower y ∈ [0, 0.4] and the upper y ∈ [0.6, 1]: a
// point of cell 0 belongs to the piece nearest to it (the one holding it, on its face
// too), to both at equal distances, and the
// answers depend neither on the order the pieces are asked in (each thread caches the
// last point's distance to the cell) nor on another evaluator asked about the same point
// in between, one whose lower bar ends at y = 0.2.
TEST(PieceBasisEvaluator, APointBelongsToItsCellsNearestPieces) {
  const Eigen::Vector3i resolution(3, 1, 2);
  const VolumeMesh background = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1)),
                                                Eigen::Vector3i(2, 1, 1), ElementType::hex8);
  const auto bars = [&](double lower_top) {
    return concatenate(box_tetrahedra({0.5, 0, 0}, {2, lower_top, 1}, resolution),
                       box_tetrahedra({0.5, 0.6, 0}, {2, 1, 1}, resolution));
  };
  const VolumeMesh embedded = bars(0.4), narrower_embedded = bars(0.2);
  const PieceMesh pieces = piece_mesh(background, find_cell_pieces(background, embedded));
  const PieceMesh narrower_pieces = piece_mesh(background, find_cell_pieces(background, narrower_embedded));
  ASSERT_EQ(pieces.mesh.cells.rows(), 4);
  ASSERT_EQ(narrower_pieces.mesh.cells.rows(), 4);
  const std::vector<int> kept{0, 1, 2, 3};
  const PieceBasisEvaluator evaluator(pieces.mesh, pieces, kept, embedded);
  const PieceBasisEvaluator narrower(narrower_pieces.mesh, narrower_pieces, kept, narrower_embedded);
  const int lower_count = 6 * resolution.prod();  // the lower bar's tetrahedra come first
  // The kept cell of cell 0 holding the lower bar, in each.
  const int lower = pieces.tetrahedra[0].front() < lower_count ? 0 : 1;
  const int narrower_lower = narrower_pieces.tetrahedra[0].front() < lower_count ? 0 : 1;
  std::vector<int> basis;
  std::vector<double> values;
  const auto belongs = [&](const PieceBasisEvaluator& asked, int cell, double y) {
    return asked.evaluate_inside(cell, Eigen::Vector3d(0.7, y, 0.5), basis, values);
  };
  for (const double y : {0.2, 0.45, 0.58, 0.9})
    for (const int first : {0, 1}) {  // both orders
      const bool nearer_lower = y < 0.5, narrower_nearer_lower = y < 0.4;
      EXPECT_EQ(belongs(evaluator, first, y), (first == lower) == nearer_lower) << y;
      EXPECT_EQ(belongs(narrower, first, y), (first == narrower_lower) == narrower_nearer_lower) << y;
      EXPECT_EQ(belongs(evaluator, 1 - first, y), (1 - first == lower) == nearer_lower) << y;
      EXPECT_EQ(belongs(narrower, 1 - first, y), (1 - first == narrower_lower) == narrower_nearer_lower) << y;
    }
  EXPECT_TRUE(belongs(evaluator, lower, 0.5));  // 0.1 from each bar
  EXPECT_TRUE(belongs(evaluator, 1 - lower, 0.5));
  // On the lower bar's face, and a rounding off it (no tetrahedron holds the point by more
  // than rounding, so the pieces are searched): the lower bar's alone.
  for (const double y : {0.4, 0.4 + 1e-14}) {
    EXPECT_TRUE(belongs(evaluator, lower, y)) << y;
    EXPECT_FALSE(belongs(evaluator, 1 - lower, y)) << y;
  }
  EXPECT_FALSE(belongs(evaluator, 2, 0.2));  // cell 1's pieces: the point is not in cell 1
}

// A box filling the cell [0, 1]³ and half of [1, 2] × [0, 1]²: the first is filled, the
// second not; a box short of the first cell's top by 1e-9 fills no cell. The rules made
// with these flags (the filled cell's standard rule, unclipped) are those made by clipping.
TEST(CellPieces, OnlyCellsTheMaterialFillsAreFilledAndTheirRulesAreTheClippedOnes) {
  const VolumeMesh background = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1)),
                                                Eigen::Vector3i(2, 1, 1), ElementType::hex8);
  for (const double top : {1.0, 1.0 - 1e-9}) {
    const VolumeMesh embedded = box_tetrahedra({0, 0, 0}, {1.5, 1, top}, Eigen::Vector3i(3, 2, 2));
    const CellPieces pieces = find_cell_pieces(background, embedded);
    EXPECT_EQ(pieces.filled, (std::vector<char>{top == 1.0, 0}));
    const PieceMesh mesh = piece_mesh(background, pieces);
    CellRuleReuse reuse;
    reuse.filled = &mesh.filled;
    const CellRules flagged = compute_cell_rules(mesh.mesh, embedded, {4}, &mesh.tetrahedra, &reuse);
    const CellRules clipped = compute_cell_rules(mesh.mesh, embedded, {4}, &mesh.tetrahedra);
    ASSERT_EQ(flagged.cells.size(), clipped.cells.size());
    for (std::size_t c = 0; c < clipped.cells.size(); ++c) {
      EXPECT_EQ(flagged.cells[c].kind, clipped.cells[c].kind);
      EXPECT_EQ(flagged.cells[c].rule.points, clipped.cells[c].rule.points);
      EXPECT_EQ(flagged.cells[c].rule.weights, clipped.cells[c].rule.weights);
      EXPECT_NEAR(flagged.cells[c].clipped_volume, clipped.cells[c].clipped_volume, 1e-14);
    }
    EXPECT_EQ(flagged.cells[0].kind, top == 1.0 ? CellKind::inside : CellKind::cut);
  }
}

}  // namespace
}  // namespace altfem::fcm
