// The parts a method composes (issue #14, items 1 and 5): embedding through a
// method's own basis evaluator (discontinuous constants on two boxes), node-based
// Dirichlet conditions, and Lagrange tabulation with per-cell rules and materials.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/common/error.hpp"
#include "shared/fem/nodal_dirichlet.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/quadrature/reference_rules.hpp"
#include "shared/simulation/basis_embedding.hpp"
#include "tests/unit/fem/test_meshes.hpp"

namespace altfem {
namespace {

// Box e = [e, e+1] × [0,1]², one basis function (index e) equal to 1 on it: a
// discontinuous piecewise-constant basis.
class TwoBoxConstants final : public ElementBasisEvaluator {
public:
  explicit TwoBoxConstants(BoundaryPointRule rule) : rule_(rule) {}
  int element_count() const override { return 2; }
  Eigen::AlignedBox3d element_bounds(int e) const override {
    return {Eigen::Vector3d(e, 0, 0), Eigen::Vector3d(e + 1, 1, 1)};
  }
  bool evaluate_inside(int e, const Eigen::Vector3d& x, std::vector<int>& basis,
                       std::vector<double>& values) const override {
    Eigen::AlignedBox3d box = element_bounds(e);
    box.min().array() -= 1e-12;
    box.max().array() += 1e-12;
    if (!box.contains(x)) return false;
    basis = {e};
    values = {1.0};
    return true;
  }
  double evaluate_nearest(const Eigen::Vector3d& x, std::vector<int>& basis,
                          std::vector<double>& values) const override {
    const double distances[2] = {element_bounds(0).exteriorDistance(x), element_bounds(1).exteriorDistance(x)};
    const int nearest = distances[1] < distances[0] ? 1 : 0;
    basis = {nearest};
    values = {1.0};
    return distances[nearest];
  }
  BoundaryPointRule boundary_rule() const override { return rule_; }

private:
  BoundaryPointRule rule_;
};

TEST(BasisEmbedding, BoundaryRuleDecidesSharedFacePointsAndOutsidePointsUseTheNearest) {
  Eigen::MatrixXd points(5, 3);
  points << 0.5, 0.5, 0.5,  // inside box 0
      1.5, 0.2, 0.7,        // inside box 1
      1.0, 0.3, 0.6,        // on the shared face
      2.5, 0.5, 0.5,        // 0.5 beyond box 1
      -0.2, 0.5, 1.1;       // beyond box 0 by (0.2, 0, 0.1)
  Eigen::VectorXd u(6);
  u << 1, 0, 0, 3, -1, 0;  // box 0 moves by (1,0,0), box 1 by (3,-1,0)
  const Eigen::RowVector3d first(1, 0, 0), second(3, -1, 0);

  const BasisEmbedding first_element(TwoBoxConstants(BoundaryPointRule::first_element), points);
  const BasisEmbedding average(TwoBoxConstants(BoundaryPointRule::average), points);
  for (const BasisEmbedding* embedding : {&first_element, &average}) {
    const Eigen::MatrixXd d = embedding->displacement(u);
    EXPECT_EQ(d.row(0), first);
    EXPECT_EQ(d.row(1), second);
    EXPECT_EQ(d.row(3), second);
    EXPECT_EQ(d.row(4), first);
    EXPECT_EQ(embedding->outside_count(), 2);
    EXPECT_NEAR(embedding->max_outside_distance(), 0.5, 1e-15);
  }
  EXPECT_EQ(first_element.displacement(u).row(2), first);
  EXPECT_EQ(average.displacement(u).row(2), (first + second) / 2);
}

DirichletCondition box_condition(const Eigen::AlignedBox3d& box, Motion motion, std::array<bool, 3> components,
                                 int index) {
  DirichletCondition condition;
  condition.region.kind = RegionKind::box;
  condition.region.box = box;
  condition.motion = motion;
  condition.components = components;
  condition.pointer = "/boundary_conditions/" + std::to_string(index);
  condition.region.pointer = condition.pointer + "/region";
  return condition;
}

TEST(NodalDirichlet, SortedDofsLastConditionWinsAndEmptyRegionsAreInputErrors) {
  const VolumeMesh mesh = structured_grid(test::unit_cube(), {2, 2, 2}, ElementType::hex8);
  // 0: x ≤ 0.5 fixed, every component; 1: x = 0 translating along y at 2 m/s, y only.
  Motion translate;
  translate.kind = MotionKind::translate;
  translate.velocity = Eigen::Vector3d(0, 2, 0);
  const std::vector<DirichletCondition> conditions{
      box_condition({Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(0.5, 2, 2)}, Motion{}, {true, true, true}, 0),
      box_condition({Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(0.0, 2, 2)}, translate, {false, true, false}, 1)};
  const DirichletDofs dirichlet = nodal_dirichlet(mesh.nodes, conditions, "scene.json", "the fem mesh");

  std::vector<int> expected;
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node)
    if (mesh.nodes(node, 0) <= 0.5 + 1e-12)
      for (int k = 0; k < 3; ++k) expected.push_back(3 * static_cast<int>(node) + k);
  EXPECT_EQ(dirichlet.dofs, expected);  // sorted, each once
  const Eigen::VectorXd prescribed = dirichlet.prescribed(1.5);
  ASSERT_EQ(prescribed.size(), static_cast<Eigen::Index>(expected.size()));
  for (size_t i = 0; i < expected.size(); ++i) {
    const int node = expected[i] / 3, component = expected[i] % 3;
    const bool moving = std::abs(mesh.nodes(node, 0)) < 1e-12 && component == 1;
    EXPECT_EQ(prescribed[static_cast<Eigen::Index>(i)], moving ? 3.0 : 0.0) << "dof " << expected[i];
  }

  auto with_empty = conditions;
  with_empty.push_back(
      box_condition({Eigen::Vector3d(5, 5, 5), Eigen::Vector3d(6, 6, 6)}, Motion{}, {true, true, true}, 2));
  try {
    nodal_dirichlet(mesh.nodes, with_empty, "scene.json", "the fem mesh");
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/boundary_conditions/2/region"), std::string::npos) << error.what();
  }
}

TEST(TabulateLagrange, CustomCellRuleAndMaterialsPerCell) {
  const VolumeMesh mesh = structured_grid(test::unit_cube(), {2, 2, 2}, ElementType::hex8);
  const int custom_cell = 3;
  // hex_rule(3) squeezed into the half ξ ∈ [−1, 0] of the reference cube.
  QuadratureRule half = hex_rule(3);
  half.points.col(0) = (half.points.col(0).array() - 1) / 2;
  half.weights /= 2;
  LagrangeCellRules rules{hex_rule(3), {{custom_cell, half}}, {0, 1, 0, 2, 0, 1, 0, 2}};
  const TabulatedElements elements = tabulate_lagrange(mesh, rules);
  const TabulatedElements standard = tabulate_lagrange(mesh, 3);
  ASSERT_EQ(elements.size(), 8);
  const Eigen::VectorXd x = mesh.nodes.col(0);
  for (int e = 0; e < 8; ++e) {
    const ElementView element = elements[e];
    EXPECT_EQ(element.material, rules.materials[e]);
    double volume = 0, first_moment = 0;
    for (int q = 0; q < element.point_count(); ++q) {
      volume += element.weights[q];
      for (int a = 0; a < element.basis_count(); ++a)
        first_moment += element.weights[q] * element.values(q, a) * x[element.basis[a]];
    }
    const double x_min = mesh.nodes(mesh.cells(e, 0), 0);
    if (e == custom_cell) {
      // Half the cell, [x_min, x_min + 1/4] along x: volume 1/16, centroid x_min + 1/8.
      EXPECT_NEAR(volume, 1.0 / 16, 1e-14);
      EXPECT_NEAR(first_moment, (x_min + 0.125) / 16, 1e-14);
    } else {
      EXPECT_NEAR(volume, 1.0 / 8, 1e-14);
      ASSERT_EQ(element.point_count(), standard[e].point_count());
      for (int q = 0; q < element.point_count(); ++q) EXPECT_EQ(element.weights[q], standard[e].weights[q]);
    }
  }
}

}  // namespace
}  // namespace altfem
