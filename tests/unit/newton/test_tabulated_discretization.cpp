// TabulatedDiscretization built from parts (issue #14, items 3–4): a non-Lagrange
// basis (two cubes with degree-1 monomials each) with a block-per-element explicit
// mass and a face term, held by a weakly imposed clamp with no constrained DOF; a
// Lagrange mesh with the lumped mass; and TimeIntegrator's check that the mass and
// Hessian patterns are one.
#include <gtest/gtest.h>

#include <stdexcept>

#include "shared/assembly/face_assembler.hpp"
#include "shared/assembly/jump_penalty_kernel.hpp"
#include "shared/assembly/tabulated_discretization.hpp"
#include "shared/common/eigen_decompositions.hpp"
#include "shared/common/error.hpp"
#include "shared/fem/lagrange_discretization.hpp"
#include "shared/solve/time_integrator.hpp"
#include "tests/unit/assembly/face_fixture.hpp"
#include "tests/unit/fem/test_meshes.hpp"

namespace altfem {
namespace {

const Eigen::Vector3d gravity(0.0, 0.0, -9.81);

// The two cubes; with `clamped`, a jump penalty η on the face between them and on cube
// 0's face x = 0 (a weak clamp).
struct TwoCubes {
  std::unique_ptr<Material> material = make_material(MaterialModel::linear, 1e5, 0.3, 1000);
  TabulatedFaces faces;
  std::unique_ptr<TabulatedDiscretization> discretization;

  explicit TwoCubes(bool clamped) {
    DiscretizationParts parts;
    parts.elements = test::two_cube_elements(3);
    parts.materials = {material.get()};
    parts.explicit_mass = ExplicitMassKind::block_per_element;
    if (clamped) {
      faces = test::two_cube_face(3);
      test::add_clamped_face(faces, 3);
      parts.terms.push_back(
          std::make_unique<FaceAssembler<JumpPenaltyKernel>>(faces, JumpPenaltyKernel(std::vector<double>{1e6, 1e6})));
      parts.conditions_weakly = true;
    }
    discretization = std::make_unique<TabulatedDiscretization>(std::move(parts));
  }
};

TEST(TabulatedDiscretization, BlockPerElementMassOfMonomialCubes) {
  const TwoCubes cubes(false);
  const Discretization& discretization = *cubes.discretization;
  ASSERT_EQ(discretization.dof_count(), 24);
  const Eigen::VectorXd load = discretization.body_force(gravity);
  EXPECT_LT((discretization.explicit_body_force(gravity) - load).norm(), 1e-14 * load.norm());
  // Only the constants integrate to non-zero (the others are centred): ρ V g on each.
  for (int a = 0; a < 8; ++a) {
    const Eigen::Vector3d expected = a % 4 == 0 ? Eigen::Vector3d(1000 * gravity) : Eigen::Vector3d::Zero();
    EXPECT_LT((load.segment<3>(3 * a) - expected).norm(), 1e-9) << "basis " << a;
  }
  // The block mass is the consistent mass: M⁻¹ (M v) = v, and M⁻¹ f(g) = g on the
  // constants and 0 on the centred monomials (a uniform acceleration).
  const ExplicitMass& mass = discretization.explicit_mass();
  const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(24, -1, 2);
  EXPECT_LT((mass.multiply(v) - discretization.mass_matrix() * v).norm(),
            1e-12 * (discretization.mass_matrix() * v).norm());
  EXPECT_LT((mass.solve(mass.multiply(v)) - v).norm(), 1e-12 * v.norm());
  const Eigen::VectorXd acceleration = mass.solve(load);
  for (int a = 0; a < 8; ++a)
    EXPECT_LT((acceleration.segment<3>(3 * a) - (a % 4 == 0 ? gravity : Eigen::Vector3d::Zero())).norm(), 1e-12);
}

TEST(TabulatedDiscretization, LumpedExplicitBodyForceIsLumpedMassTimesAcceleration) {
  const auto material = make_material(MaterialModel::linear, 1e5, 0.3, 1000);
  const auto fem = make_lagrange_discretization(
      test::distorted_grid(test::unit_cube(), {2, 2, 2}, ElementType::tet10, 0.15, 3), *material, {}, 4);
  const auto& lumped = dynamic_cast<const DiagonalMass&>(fem->explicit_mass()).diagonal();
  const Eigen::VectorXd force = fem->explicit_body_force(gravity);
  ASSERT_EQ(force.size(), lumped.size());
  for (Eigen::Index dof = 0; dof < force.size(); ++dof) EXPECT_EQ(force[dof], lumped[dof] * gravity[dof % 3]);
  EXPECT_NEAR(force.sum(), 1000 * gravity.sum(), 1e-9);  // the lumped mass keeps ρV
}

// A rule with a negative weight (a cone rule on a cell that is not star-shaped) can make
// the HRZ-lumped mass of a basis function negative: a NumericalError (exit 3) naming the
// basis function and its element, not an invalid_argument from the diagonal mass.
TEST(TabulatedDiscretization, NonPositiveLumpedMassIsANumericalErrorNamingTheElement) {
  const auto material = make_material(MaterialModel::linear, 1e5, 0.3, 1000);
  DiscretizationParts parts;
  // Two points, N_0 = 1 at the first and N_1 = 1 at the second of weight −0.6: the mass
  // diagonal is (1, −0.6), the volume 0.4.
  const std::vector<int> basis{0, 1};
  const std::vector<double> weights{1.0, -0.6};
  const Eigen::Matrix2d values = Eigen::Matrix2d::Identity();
  Eigen::MatrixXd gradients(4, 3);
  gradients << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0;
  parts.elements.add(basis, weights, values, gradients);
  parts.materials = {material.get()};
  try {
    TabulatedDiscretization discretization(std::move(parts));
    FAIL() << "no error";
  } catch (const NumericalError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("basis function 1"), std::string::npos) << message;
    EXPECT_NE(message.find("0 (a negative weight)"), std::string::npos) << message;
  }
}

TEST(TabulatedDiscretization, WeakClampHoldsTheCubesUnderGravity) {
  const TwoCubes cubes(true);
  const Discretization& discretization = *cubes.discretization;
  EXPECT_TRUE(discretization.imposes_conditions_weakly());
  EXPECT_TRUE(discretization.constrained_dofs().empty());
  EXPECT_TRUE(discretization.hessian_is_constant());
  const auto solver = make_linear_solver({});
  IntegratorOptions options;
  options.gravity = gravity;
  options.tolerance = 1e-10;
  TimeIntegrator integrator(discretization, *solver, options);
  State state{Eigen::VectorXd::Zero(24), Eigen::VectorXd::Zero(24)};
  const StepReport report = integrator.step(state);
  EXPECT_LE(report.residual, integrator.absolute_tolerance());

  // Linear: the equilibrium solves K u = f(g) with the face terms in K.
  Eigen::SparseMatrix<double> hessian = discretization.hessian_pattern();
  discretization.hessian(Eigen::VectorXd::Zero(24), hessian, false);
  const Eigen::VectorXd expected = Eigen::MatrixXd(hessian).llt().solve(discretization.body_force(gravity));
  ASSERT_TRUE(state.displacement.allFinite());
  EXPECT_LT((state.displacement - expected).norm(), 1e-8 * expected.norm());
  // It sags: cube 1's mean displacement (its constant's coefficient) points down and
  // exceeds cube 0's, which is held at x = 0.
  EXPECT_LT(state.displacement[3 * 4 + 2], state.displacement[3 * 0 + 2]);
  EXPECT_LT(state.displacement[3 * 0 + 2], 0.0);
}

// A Discretization whose mass has one entry more than its Hessian pattern.
class MismatchedPatterns final : public Discretization {
public:
  MismatchedPatterns() : mass_(6, 6), pattern_(6, 6), explicit_mass_(Eigen::VectorXd::Ones(6)) {
    for (int i = 0; i < 6; ++i) {
      mass_.insert(i, i) = 1.0;
      pattern_.insert(i, i) = 0.0;
    }
    mass_.insert(0, 1) = 0.0;
    mass_.makeCompressed();
    pattern_.makeCompressed();
  }
  int dof_count() const override { return 6; }
  double energy(const Eigen::VectorXd& u) const override { return 0.5 * u.squaredNorm(); }
  void gradient(const Eigen::VectorXd& u, Eigen::VectorXd& gradient) const override { gradient = u; }
  void hessian(const Eigen::VectorXd&, Eigen::SparseMatrix<double>& hessian, bool) const override {
    hessian = pattern_;
    for (int i = 0; i < 6; ++i) hessian.coeffRef(i, i) = 1.0;
  }
  const Eigen::SparseMatrix<double>& hessian_pattern() const override { return pattern_; }
  bool hessian_is_constant() const override { return true; }
  const Eigen::SparseMatrix<double>& mass_matrix() const override { return mass_; }
  const ExplicitMass& explicit_mass() const override { return explicit_mass_; }
  Eigen::VectorXd body_force(const Eigen::Vector3d& a) const override { return a.replicate(2, 1); }
  const std::vector<int>& constrained_dofs() const override { return no_dofs_; }
  Eigen::VectorXd prescribed_displacement(double) const override { return {}; }

private:
  Eigen::SparseMatrix<double> mass_, pattern_;
  DiagonalMass explicit_mass_;
  std::vector<int> no_dofs_;
};

TEST(TimeIntegrator, RejectsMassAndHessianWithDifferentPatterns) {
  const MismatchedPatterns discretization;
  const auto solver = make_linear_solver({});
  IntegratorOptions options;
  options.gravity = gravity;
  options.kind = IntegrationScheme::backward_euler;
  options.time_step = 0.01;
  // Adding the mass into the Hessian (Discretization::add_mass) finds them different.
  TimeIntegrator dynamic(discretization, *solver, options);
  State state{Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6)};
  EXPECT_THROW(dynamic.step(state), std::logic_error);
  // A static run never adds the mass to the Hessian, and never asks for it (dg builds
  // it only when asked, issue #35).
  options.kind = IntegrationScheme::static_equilibrium;
  TimeIntegrator equilibrium(discretization, *solver, options);
  State at_rest{Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6)};
  EXPECT_NO_THROW(equilibrium.step(at_rest));
}

}  // namespace
}  // namespace altfem
