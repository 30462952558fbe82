// The MFS cells' volume rules (harmonic_cell_rule): each kind gives the shared rule it
// names (cone, simplified cone, subdivision, Monte Carlo from the cell's seed), and a cell
// whose subdivision keeps no box is a numerical failure naming it, not an unintegrated cell.
#include <gtest/gtest.h>

#include <string>

#include "polyhedral/harmonic_element_bases.hpp"
#include "shared/common/error.hpp"
#include "shared/quadrature/polyhedron_monte_carlo_rule.hpp"
#include "shared/quadrature/polyhedron_subdivision_rule.hpp"
#include "tests/unit/polyhedra.hpp"

namespace altfem::harmonic {
namespace {

void expect_same_rule(const PolyhedronRule& a, const PolyhedronRule& b) {
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.weights, b.weights);
}

TEST(HarmonicCellRule, EachKindIsTheSharedRuleItNames) {
  const Polyhedron prism = test::l_prism();
  expect_same_rule(harmonic_cell_rule(prism, 3, {.simplifier = std::nullopt}, 0), polyhedron_rule(prism, 3));
  const PolyhedronRule simplified = harmonic_cell_rule(prism, 2, {}, 0);
  const PolyhedronRule cone = polyhedron_rule(prism, 2);
  EXPECT_EQ(simplified.weights.size(), cone.weights.size());  // the default: not simplified
  const PolyhedronRule caratheodory =
      harmonic_cell_rule(prism, 2, {.simplifier = SimplificationMethod::caratheodory}, 0);
  EXPECT_LE(caratheodory.weights.size(), 10);  // C(2 + 3, 3)
  EXPECT_LT(caratheodory.weights.size(), cone.weights.size());
  EXPECT_NEAR(caratheodory.weights.sum(), 2.1, 1e-12);
  expect_same_rule(harmonic_cell_rule(prism, 2, {.kind = HarmonicRuleKind::subdivision, .subdivision_levels = 2}, 0),
                   polyhedron_subdivision_rule(prism, 2, 2));
  const HarmonicQuadrature monte_carlo{.kind = HarmonicRuleKind::monte_carlo, .monte_carlo_points = 300};
  expect_same_rule(harmonic_cell_rule(prism, 2, monte_carlo, 5), polyhedron_monte_carlo_rule(prism, 300, 5));
}

TEST(HarmonicCellRule, ACellTheSubdivisionMissesIsANumericalFailure) {
  // A thin L: the centre of its bounding box [0,2]² × [0,0.5] lies outside it, so with one
  // box (0 levels) no point is kept; with 3 levels (boxes 0.25 wide) its arms keep boxes.
  const Polyhedron thin = test::prism({{0, 0}, {2, 0}, {2, 0.2}, {0.2, 0.2}, {0.2, 2}, {0, 2}}, 0.5);
  PolyhedralMesh mesh;
  mesh.nodes = thin.vertices;
  mesh.faces = thin.faces;
  const auto faces = static_cast<int>(thin.faces.size());
  mesh.face_cells = Eigen::MatrixXi::Constant(faces, 2, -1);
  mesh.face_cells.col(0).setZero();
  mesh.cell_faces = {std::vector<int>(static_cast<size_t>(faces))};
  for (int face = 0; face < faces; ++face) mesh.cell_faces[0][face] = face;
  mesh.cell_kinds = {PolyhedralCellKind::cut};
  compute_polyhedral_geometry(mesh);
  const HarmonicElementBases bases(mesh, HarmonicBasisKind::automatic, {});
  ASSERT_NE(bases.mfs_basis(0), nullptr);
  try {
    bases.tabulate(2, {.kind = HarmonicRuleKind::subdivision, .subdivision_levels = 0});
    ADD_FAILURE() << "no NumericalError";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("cell 0"), std::string::npos) << error.what();
  }
  const TabulatedElements elements =
      bases.tabulate(2, {.kind = HarmonicRuleKind::subdivision, .subdivision_levels = 3});
  EXPECT_GT(elements.point_count(), 0);
}

}  // namespace
}  // namespace altfem::harmonic
