// lagrange_element_masses (no gradients tabulated) equals the reduction of the full
// tabulation, and the assembler's mass, loads and lumped mass from it equal those of
// its own elements.
#include <gtest/gtest.h>

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

INSTANTIATE_TEST_SUITE_P(Elements, LagrangeElementMasses,
                         ::testing::Values(ElementType::tet4, ElementType::tet10, ElementType::hex8, ElementType::hex20,
                                           ElementType::hex27),
                         [](const auto& info) { return std::string(element_name(info.param)); });

}  // namespace
}  // namespace altfem
