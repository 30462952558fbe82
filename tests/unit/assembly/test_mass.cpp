// Consistent and lumped (HRZ) mass: exact totals on distorted meshes.
#include <gtest/gtest.h>

#include <stdexcept>

#include "shared/assembly/element_masses.hpp"
#include "shared/assembly/tabulated_discretization.hpp"
#include "tests/unit/assembly/assembly_fixture.hpp"

namespace altfem {
namespace {

class MassOfType : public ::testing::TestWithParam<ElementType> {};

constexpr double density = 750;

TEST_P(MassOfType, ConsistentMassTotalsAndRigidTranslation) {
  const test::AssemblyProblem problem(GetParam(), {2, 3, 2}, MaterialModel::linear, density);
  SparseMatrix mass;
  problem.assembler->mass_matrix(mass);
  const double total = density * test::unit_cube().volume();  // the distortion keeps the box

  // Σ_ab M_ab of one component block = ρ ∫ (Σ_a N_a)(Σ_b N_b) = ρ V (partition of unity).
  // The mixed blocks (x–y) must be empty.
  double x_block = 0, mixed = 0;
  for (int column = 0; column < mass.outerSize(); ++column)
    for (SparseMatrix::InnerIterator it(mass, column); it; ++it) {
      if (it.row() % 3 == 0 && column % 3 == 0) x_block += it.value();
      if (it.row() % 3 != column % 3) mixed += std::abs(it.value());
    }
  EXPECT_NEAR(x_block, total, 1e-12 * total);
  EXPECT_EQ(mixed, 0.0);

  Eigen::VectorXd unit_x = Eigen::VectorXd::Zero(mass.rows());
  for (Eigen::Index i = 0; i < unit_x.size(); i += 3) unit_x[i] = 1.0;
  EXPECT_NEAR(unit_x.dot(mass * unit_x), total, 1e-12 * total);
  EXPECT_LT(Eigen::MatrixXd(mass - Eigen::SparseMatrix<double>(mass.transpose())).norm(), 1e-14 * total);
}

TEST_P(MassOfType, LumpedMassPositiveAndConserved) {
  const test::AssemblyProblem problem(GetParam(), {2, 3, 2}, MaterialModel::linear, density);
  const Eigen::VectorXd lumped = problem.assembler->lumped_mass();
  const double total = density * test::unit_cube().volume();
  ASSERT_EQ(lumped.size(), problem.assembler->dof_count());
  EXPECT_GT(lumped.minCoeff(), 0.0);
  EXPECT_NEAR(lumped.sum(), 3 * total, 3e-12 * total);
  for (Eigen::Index node = 0; node < lumped.size() / 3; ++node) {
    EXPECT_EQ(lumped[3 * node], lumped[3 * node + 1]);
    EXPECT_EQ(lumped[3 * node], lumped[3 * node + 2]);
  }
}

// What the integrators take of the mass, element by element, without a matrix of its own:
// M v and A + c M equal the assembled matrix's, for the assembler and for the
// discretization that assembles its mass only when asked.
TEST_P(MassOfType, ElementByElementProductAndSumEqualTheAssembledMass) {
  const test::AssemblyProblem problem(GetParam(), {2, 3, 2}, MaterialModel::linear, density);
  SparseMatrix mass;
  problem.assembler->mass_matrix(mass);
  const ElementMasses masses = element_masses(problem.elements);
  const Eigen::VectorXd vector = Eigen::VectorXd::Random(mass.rows());
  const Eigen::VectorXd product = mass * vector;
  EXPECT_LT((problem.assembler->mass_times(masses, vector) - product).norm(), 1e-14 * product.norm());
  SparseMatrix sum = problem.assembler->pattern();
  for (Eigen::Index k = 0; k < sum.nonZeros(); ++k) sum.valuePtr()[k] = 1.0 + k % 7;
  const SparseMatrix expected = sum + 2.5 * mass;
  problem.assembler->add_mass(masses, 2.5, sum);
  EXPECT_LT((sum - expected).norm(), 1e-14 * expected.norm());

  DiscretizationParts parts;
  parts.elements = problem.elements;
  parts.materials = {problem.material.get()};
  const TabulatedDiscretization discretization(std::move(parts));
  EXPECT_LT((discretization.mass_times(vector) - product).norm(), 1e-14 * product.norm());
  SparseMatrix hessian = discretization.hessian_pattern();
  discretization.add_mass(2.0, hessian);
  EXPECT_LT((hessian - 2.0 * mass).norm(), 1e-14 * mass.norm());
  EXPECT_LT((discretization.mass_matrix() - mass).norm(), 1e-14 * mass.norm());
  SparseMatrix other(hessian.rows(), hessian.cols());
  EXPECT_THROW(discretization.add_mass(1.0, other), std::logic_error);
}

// Tet10 is the case plain row sums get wrong (zero or negative corner masses).
INSTANTIATE_TEST_SUITE_P(ElasticAssembler, MassOfType,
                         ::testing::Values(ElementType::tet10, ElementType::tet20, ElementType::hex20,
                                           ElementType::hex27),
                         [](const auto& info) { return std::string(element_name(info.param)); });

}  // namespace
}  // namespace altfem
