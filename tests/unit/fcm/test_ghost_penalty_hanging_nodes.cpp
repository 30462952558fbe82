// The face ghost penalty on a refined grid (hexahedral_forest.hpp): the half x > 1 of
// [0, 2]³ in 2³ cubes split into eighths, so that the plane x = 1 holds a coarse cell's face
// against four finer ones and the hanging nodes on it. Its faces are the conforming ones
// and each finer face on a coarser one; its functions are the free nodes', a hanging node's
// traces added to its masters'. Checked against energies known in closed form (a kink and a
// curvature jump across the plane where the levels meet, and across a plane that crosses
// it, where the hanging nodes carry non-zero values), and polynomials of the cells' degree
// cost nothing, across the hanging nodes too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "shared/assembly/ghost_penalty_kernel.hpp"
#include "shared/cut_cells/ghost_penalty_faces.hpp"
#include "shared/mesh/hexahedral_forest.hpp"
#include "tests/unit/assembly/face_term.hpp"

namespace altfem::fcm {
namespace {

using Field = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

// Every cell counts as cut (volume fraction ½), so every interior face is penalised.
struct RefinedGrid {
  ConstrainedHexahedralMesh grid;
  GhostPenaltyFaces ghost;
};
RefinedGrid refined_grid(ElementType type) {
  const HexahedralForest cubes =
      grid_forest(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(2)), {2, 2, 2}, type);
  RefinedGrid result{forest_mesh(refine_forest(cubes, {1, 3, 5, 7})), {}};  // the cubes with x > 1
  const std::vector<double> fractions(static_cast<size_t>(result.grid.mesh.cells.rows()), 0.5);
  result.ghost = ghost_penalty_faces(result.grid.mesh, fractions, nullptr, &result.grid.constraints);
  return result;
}

// The field at the free nodes: the hanging ones follow from them.
Eigen::VectorXd free_values(const RefinedGrid& refined, const Field& field) {
  const int free_nodes = refined.grid.constraints.free_nodes;
  Eigen::VectorXd u(3 * free_nodes);
  for (int node = 0; node < free_nodes; ++node) u.segment<3>(3 * node) = field(refined.grid.mesh.nodes.row(node));
  return u;
}

// The penalty with γ_F = 1 on every face.
test::FaceTerm<GhostPenaltyKernel> unit_penalty(const RefinedGrid& refined) {
  const auto faces = static_cast<size_t>(refined.ghost.faces.size());
  return {refined.ghost.faces, GhostPenaltyKernel(refined.ghost.faces, std::vector<double>(faces, 1.0),
                                                  refined.ghost.sizes, element_degree(refined.grid.mesh.element_type))};
}

class GhostPenaltyOnARefinedGrid : public ::testing::TestWithParam<ElementType> {};

// The coarse half: 4 faces between its 4 cubes; the fine half, 2 × 4 × 4 cells: 64 faces;
// the plane x = 1: 4 coarse faces, each against 4 finer ones. h_F is 1 on the coarse faces
// and ½ on every other, the finer side's; no hanging node is left in a face's functions.
TEST_P(GhostPenaltyOnARefinedGrid, PairsEachFinerFaceWithTheCoarserCellAcrossIt) {
  const RefinedGrid refined = refined_grid(GetParam());
  ASSERT_GT(refined.grid.constraints.hanging_nodes(), 0);
  ASSERT_EQ(refined.ghost.faces.size(), 4 + 64 + 16);
  EXPECT_EQ(std::count(refined.ghost.sizes.begin(), refined.ghost.sizes.end(), 1.0), 4);
  EXPECT_EQ(std::count(refined.ghost.sizes.begin(), refined.ghost.sizes.end(), 0.5), 64 + 16);
  const BasisGroups& functions = refined.ghost.faces.basis_groups();
  for (int face = 0; face < functions.size(); ++face)
    for (const int node : functions[face]) EXPECT_LT(node, refined.grid.constraints.free_nodes);
}

// u = ((x − 1)₊, 0, 0): [∂ₙu] = ±1 on x = 1 only, on the 16 finer faces (h_F = ½, area 4 in
// all), so E = ½ · ½ · 4 = 1. Left out, the pairs across the plane would cost nothing.
TEST_P(GhostPenaltyOnARefinedGrid, AKinkWhereTheLevelsMeetCostsHalfTheFinerHTimesItsArea) {
  const RefinedGrid refined = refined_grid(GetParam());
  const Eigen::VectorXd u =
      free_values(refined, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(std::max(x[0] - 1, 0.0), 0, 0); });
  EXPECT_NEAR(unit_penalty(refined).assembler.energy(u), 1.0, 1e-12);
}

// u = (0, (y − 1)₊, 0): the kink lies on y = 1, coarse faces (h_F = 1, area 2) and fine ones
// (h_F = ½, area 2): E = ½ (1 · 2 + ½ · 2) = 3/2. On x = 1 the hanging nodes above y = 1
// carry u, so the coarse-fine faces cost nothing only if their traces take it from the
// masters.
TEST_P(GhostPenaltyOnARefinedGrid, AKinkAcrossTheLevelsCostsEachSidesHTimesItsArea) {
  const RefinedGrid refined = refined_grid(GetParam());
  const Eigen::VectorXd u =
      free_values(refined, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(0, std::max(x[1] - 1, 0.0), 0); });
  EXPECT_NEAR(unit_penalty(refined).assembler.energy(u), 1.5, 1e-12);
}

// Quadratic cells, u = (0, 0, (x − 1)₊²): [∂ₙu] = 0 and [∂ₙ²u] = ±2 on x = 1, so
// E = ½ (h_F³ / (2!)²) · 4 · 4 = 2 h_F³ = ¼; and (0, 0, (y − 1)₊²): ½ (1/4 · 4 · 2 + 1/32 · 4 · 2)
// = 9/8, the hanging nodes on x = 1 carrying (y − 1)² from their masters.
TEST(GhostPenaltyOnARefinedGridQuadratic, CurvatureJumpsCostTheSecondDerivativeTerm) {
  for (const ElementType type : {ElementType::hex20, ElementType::hex27}) {
    const RefinedGrid refined = refined_grid(type);
    const auto term = unit_penalty(refined);
    const Eigen::VectorXd where_levels_meet = free_values(
        refined, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(0, 0, std::pow(std::max(x[0] - 1, 0.0), 2)); });
    EXPECT_NEAR(term.assembler.energy(where_levels_meet), 0.25, 1e-12) << element_name(type);
    const Eigen::VectorXd across_levels = free_values(
        refined, [](const Eigen::Vector3d& x) { return Eigen::Vector3d(0, 0, std::pow(std::max(x[1] - 1, 0.0), 2)); });
    EXPECT_NEAR(term.assembler.energy(across_levels), 9.0 / 8, 1e-12) << element_name(type);
  }
}

// The constrained space holds every polynomial of the cells' complete degree, and those
// have no jumps: the patch test survives the hanging nodes.
TEST_P(GhostPenaltyOnARefinedGrid, PolynomialsOfTheCellsDegreeCostNothing) {
  const RefinedGrid refined = refined_grid(GetParam());
  const auto term = unit_penalty(refined);
  const Eigen::VectorXd affine = free_values(refined, [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(0.3 * x[0] - 0.2 * x[1] + 0.1, 0.5 * x[2] + 0.4 * x[0], -0.7 * x[1] + 0.2 * x[2]);
  });
  EXPECT_NEAR(term.assembler.energy(affine), 0.0, 1e-24);
  EXPECT_LT(term.gradient(affine).cwiseAbs().maxCoeff(), 1e-12);
  if (element_degree(GetParam()) < 2) return;
  const Eigen::VectorXd quadratic = free_values(refined, [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(x[0] * x[1] - 0.5 * x[2] * x[2], x[1] * x[1] + x[0], 0.3 * x[0] * x[2] - x[1] * x[2]);
  });
  EXPECT_NEAR(term.assembler.energy(quadratic), 0.0, 1e-20);
}

INSTANTIATE_TEST_SUITE_P(Cells, GhostPenaltyOnARefinedGrid,
                         ::testing::Values(ElementType::hex8, ElementType::hex20, ElementType::hex27),
                         [](const auto& info) { return std::string(element_name(info.param)); });

}  // namespace
}  // namespace altfem::fcm
