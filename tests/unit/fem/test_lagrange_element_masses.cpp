// lagrange_element_masses (no gradients tabulated) equals the reduction of the full
// tabulation, and the assembler's mass, loads and lumped mass from it equal those of
// its own elements.
#include <gtest/gtest.h>
#include <omp.h>

#include "shared/assembly/elastic_assembler.hpp"
#include "shared/fem/lagrange_element_masses.hpp"
#include "shared/quadrature/reference_rules.hpp"
#include "tests/unit/fem/test_meshes.hpp"

namespace altfem {
namespace {

class LagrangeElementMasses : public ::testing::TestWithParam<ElementType> {};

void expect_reduction_of_the_tabulation(const VolumeMesh& mesh);

// On a distorted grid (curved hexahedra: a determinant per point) and on a straight one
// (affine cells: one determinant per cell).
TEST_P(LagrangeElementMasses, EqualTheReductionOfTheTabulation) {
  for (const double distortion : {0.2, 0.0}) {
    SCOPED_TRACE("distortion " + std::to_string(distortion));
    expect_reduction_of_the_tabulation(test::distorted_grid(test::unit_cube(), {2, 2, 2}, GetParam(), distortion, 7));
  }
}

void expect_reduction_of_the_tabulation(const VolumeMesh& mesh) {
  const ElementType type = mesh.element_type;
  const bool tets = element_shape(type) == ElementShape::tetrahedron;
  LagrangeCellRules rules{tets ? tet_rule(4) : hex_rule(4), {}, {}};
  rules.custom.emplace(1, tets ? tet_rule(7) : hex_rule(7));  // a cell with a rule of its own
  const ElementMasses direct = lagrange_element_masses(mesh, rules);
  const TabulatedElements tabulated = tabulate_lagrange(mesh, rules);
  const ElementMasses reduced = element_masses(tabulated);
  ASSERT_EQ(direct.size(), reduced.size());
  for (int e = 0; e < direct.size(); ++e) {
    EXPECT_LT((direct.matrices[e] - reduced.matrices[e]).norm(), 1e-14 * reduced.matrices[e].norm());
    EXPECT_LT((direct.integrals[e] - reduced.integrals[e]).norm(), 1e-14 * reduced.integrals[e].norm());
    EXPECT_NEAR(direct.volumes[e], reduced.volumes[e], 1e-14 * reduced.volumes[e]);
  }

  const auto material = make_material(MaterialModel::linear, 1e6, 0.3, 1200);
  const ElasticAssembler assembler(tabulated, {material.get()});
  SparseMatrix own, given;
  assembler.mass_matrix(own);
  assembler.mass_matrix(direct, given);
  EXPECT_LT((own - given).norm(), 1e-13 * own.norm());
  const Eigen::Vector3d acceleration(0.3, -9.81, 1.0);
  EXPECT_LT((assembler.body_force(acceleration) - assembler.body_force(direct, acceleration)).norm(),
            1e-13 * assembler.body_force(acceleration).norm());
  EXPECT_LT((assembler.lumped_mass() - assembler.lumped_mass(direct)).norm(), 1e-13 * assembler.lumped_mass().norm());
  // The total mass is ρ × the volume.
  EXPECT_NEAR(assembler.lumped_mass(direct).sum() / 3, 1200.0, 1e-9);
}

// A rule of more points than one thread sums (a sharpened pencil's tip cell) is summed in
// chunks by every thread: the same masses as the tabulation's reduction, on a straight and
// on a curved grid, and the same on one thread as on two.
TEST(LagrangeElementMassesOfALargeRule, EqualTheReductionOfTheTabulation) {
  for (const double distortion : {0.0, 0.2}) {
    SCOPED_TRACE("distortion " + std::to_string(distortion));
    const VolumeMesh mesh = test::distorted_grid(test::unit_cube(), {2, 1, 1}, ElementType::hex20, distortion, 7);
    QuadratureRule large;  // 60,000 points spread over the reference cube, positive weights
    const Eigen::Index points = 60000;
    std::srand(5);
    large.points = 0.999 * Eigen::MatrixXd::Random(points, 3);
    large.weights = (Eigen::VectorXd::Random(points).array() + 1.5).matrix();
    large.weights *= 8.0 / large.weights.sum();
    large.strength = 1;
    LagrangeCellRules rules{hex_rule(4), {}, {}};
    rules.custom.emplace(1, large);
    const ElementMasses direct = lagrange_element_masses(mesh, rules);
    const ElementMasses reduced = element_masses(tabulate_lagrange(mesh, rules));
    EXPECT_LT((direct.matrices[1] - reduced.matrices[1]).norm(), 1e-13 * reduced.matrices[1].norm());
    EXPECT_LT((direct.integrals[1] - reduced.integrals[1]).norm(), 1e-13 * reduced.integrals[1].norm());
    EXPECT_NEAR(direct.volumes[1], reduced.volumes[1], 1e-13 * reduced.volumes[1]);
    EXPECT_EQ(direct.matrices[1], direct.matrices[1].transpose());
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const ElementMasses one_thread = lagrange_element_masses(mesh, rules);
    omp_set_num_threads(threads);
    EXPECT_EQ(one_thread.matrices[1], direct.matrices[1]);
    EXPECT_EQ(one_thread.integrals[1], direct.integrals[1]);
  }
}

INSTANTIATE_TEST_SUITE_P(Elements, LagrangeElementMasses,
                         ::testing::Values(ElementType::tet4, ElementType::tet10, ElementType::hex8, ElementType::hex20,
                                           ElementType::hex27),
                         [](const auto& info) { return std::string(element_name(info.param)); });

}  // namespace
}  // namespace altfem
