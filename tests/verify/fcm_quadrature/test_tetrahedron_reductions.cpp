// Affine cells' mass reductions summed tetrahedron by tetrahedron
// (shared/cut_cells/tetrahedron_reductions.hpp): the reduction of a cell is its material's
// ∫ N_a N_b exactly (the mass strength is the products' degree), and a rebuild that takes
// the shares of the tetrahedra an event left alone from the build before gives the
// reductions of a build from scratch bit for bit, taking every share but those of the
// tetrahedra that changed in a cell of more than a block of them, and keeping none of
// smaller cells.
#include <gtest/gtest.h>

#include <algorithm>

#include "shared/cut_cells/cell_rules.hpp"
#include "shared/fem/lagrange_element_masses.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/quadrature/reference_rules.hpp"

namespace altfem::fcm {
namespace {

CellRuleOptions mass_options() {
  CellRuleOptions options{8};
  options.simplify = false;
  options.fan = PieceFan::vertex;
  options.exact_degree = 8;  // Hex20's products
  options.reduce = true;
  return options;
}

// A body of 4 × 4 × 4 × 6 tetrahedra reaching past the unit cube's top.
VolumeMesh body() {
  return structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Constant(0.1), Eigen::Vector3d(0.9, 0.9, 1.3)),
                         Eigen::Vector3i(4, 4, 4), ElementType::tet4);
}

// Interior node `node` of `mesh` moved by a small step: the tetrahedra around it change.
VolumeMesh moved(VolumeMesh mesh, int node) {
  mesh.nodes.row(node) += Eigen::RowVector3d(0.011, -0.007, 0.005);
  return mesh;
}

int interior_node(const VolumeMesh& mesh) {
  for (Eigen::Index n = 0; n < mesh.nodes.rows(); ++n)
    if ((mesh.nodes.row(n).array() > 0.3).all() && (mesh.nodes.row(n).array() < 0.7).all()) return static_cast<int>(n);
  return -1;
}

void expect_bit_for_bit(const CellRules& rebuilt, const CellRules& scratch) {
  ASSERT_EQ(rebuilt.cells.size(), scratch.cells.size());
  for (std::size_t c = 0; c < scratch.cells.size(); ++c) {
    SCOPED_TRACE("cell " + std::to_string(c));
    EXPECT_EQ(rebuilt.cells[c].kind, scratch.cells[c].kind);
    EXPECT_EQ(rebuilt.cells[c].clipped_volume, scratch.cells[c].clipped_volume);
    EXPECT_EQ(rebuilt.cells[c].initial_points, scratch.cells[c].initial_points);
    ASSERT_EQ(rebuilt.cells[c].reduced.has_value(), scratch.cells[c].reduced.has_value());
    if (!scratch.cells[c].reduced) continue;
    EXPECT_EQ(rebuilt.cells[c].reduced->products, scratch.cells[c].reduced->products);
    EXPECT_EQ(rebuilt.cells[c].reduced->integrals, scratch.cells[c].reduced->integrals);
    EXPECT_EQ(rebuilt.cells[c].reduced->weight_sum, scratch.cells[c].reduced->weight_sum);
  }
}

TEST(TetrahedronReductions, ACellsReductionIsItsMaterialsMassIntegralsExactly) {
  const VolumeMesh cell = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                                          Eigen::Vector3i(1, 1, 1), ElementType::hex20);
  const CellRules rules = compute_cell_rules(cell, body(), mass_options());
  ASSERT_EQ(rules.cut_cells, 1);
  const CellRule& rule = rules.cells[0];
  EXPECT_EQ(rule.rule.points.rows(), 0);  // the reduction alone
  ASSERT_TRUE(rule.reduced.has_value());
  // The material in the cell is the box [0.1, 0.9]² × [0.1, 1]: in reference coordinates
  // [-0.8, 0.8]² × [-0.8, 1], where a Gauss rule of strength 8 integrates the products.
  QuadratureRule box = hex_rule(8);
  const Eigen::Array3d low(-0.8, -0.8, -0.8), high(0.8, 0.8, 1.0);
  for (Eigen::Index q = 0; q < box.points.rows(); ++q)
    box.points.row(q) = (low + (box.points.row(q).transpose().array() + 1) * (high - low) / 2).transpose();
  box.weights *= ((high - low) / 2).prod();
  const ReferenceProducts exact = reference_products(ElementType::hex20, box);
  EXPECT_NEAR(rule.reduced->weight_sum, exact.weight_sum, 1e-14);
  EXPECT_LE((rule.reduced->products - exact.products).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LE((rule.reduced->integrals - exact.integrals).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NEAR(rule.clipped_volume, 0.8 * 0.8 * 0.9, 1e-14);
}

TEST(TetrahedronReductions, ARebuildTakesTheSharesOfTheTetrahedraLeftAloneAndGivesTheReductionsFromScratch) {
  const VolumeMesh before = body();
  const int node = interior_node(before);
  ASSERT_GE(node, 0);
  const VolumeMesh after = moved(before, node);
  int changed = 0;  // the tetrahedra around the moved node
  for (Eigen::Index t = 0; t < before.cells.rows(); ++t) changed += (before.cells.row(t).array() == node).any();
  ASSERT_GT(changed, 0);
  // One cell holding every tetrahedron (summed block by block by all threads), and a 6³
  // grid of cells of fewer tetrahedra than a block each.
  for (const int cells : {1, 6}) {
    SCOPED_TRACE(std::to_string(cells) + "³ cells");
    const VolumeMesh grid = structured_grid(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                                            Eigen::Vector3i::Constant(cells), ElementType::hex20);
    std::vector<std::vector<int>> all(1);
    for (int t = 0; t < before.cells.rows(); ++t) all[0].push_back(t);
    const std::vector<std::vector<int>>* listed = cells == 1 ? &all : nullptr;
    const CellRuleMemory nothing;
    CellRuleMemory memory;
    CellRuleReuse first{&nothing, &memory};
    compute_cell_rules(grid, before, mass_options(), listed, &first);
    EXPECT_EQ(first.reused_tetrahedra, 0);
    CellRuleMemory next;
    CellRuleReuse rebuild{&memory, &next};
    const CellRules rebuilt = compute_cell_rules(grid, after, mass_options(), listed, &rebuild);
    expect_bit_for_bit(rebuilt, compute_cell_rules(grid, after, mass_options(), listed));
    if (cells == 1) {
      // Every share but the changed tetrahedra's taken; the rebuild remembers those it
      // took as well as those it computed.
      EXPECT_EQ(before.cells.rows(), 384);
      EXPECT_EQ(rebuild.reused_tetrahedra, 384 - changed);
      EXPECT_EQ(next.tetrahedra.size(), 384u);
    } else {
      // Cells of fewer tetrahedra than a block keep no shares; those without a changed
      // tetrahedron take their whole rules.
      EXPECT_TRUE(memory.tetrahedra.empty());
      EXPECT_EQ(rebuild.reused_tetrahedra, 0);
      EXPECT_GT(rebuild.reused, 0);
    }
  }
}

}  // namespace
}  // namespace altfem::fcm
