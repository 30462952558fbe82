// The assembled gradient and Hessian against central finite differences of the
// assembled energy and gradient, their symmetry, and the SPD projection.
#include <gtest/gtest.h>

#include <omp.h>

#include <Eigen/Eigenvalues>

#include "shared/common/eigen_decompositions.hpp"
#include "tests/unit/assembly/assembly_fixture.hpp"

namespace altfem {
namespace {

struct Case {
  ElementType type;
  MaterialModel model;
};

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  return std::string(element_name(info.param.type)) + "_" + std::string(material_model_name(info.param.model));
}

class AssemblyDerivatives : public ::testing::TestWithParam<Case> {};

// ε = 1e-6 on a unit-sized mesh: the central difference's truncation error
// (~ε² ‖Ψ'''‖) and round-off (~1e-16 |Ψ| / ε) both stay far below 1e-6 relative.
constexpr double step = 1e-6;

TEST_P(AssemblyDerivatives, GradientAndHessianMatchFiniteDifferences) {
  // ~1500 assemblies of a 48-element mesh: OpenMP's per-colour barriers would cost
  // more than the work (thread counts are test_thread_determinism's subject).
  const int saved_threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const test::AssemblyProblem problem(GetParam().type, {2, 2, 2}, GetParam().model);
  const ElasticAssembler& assembler = *problem.assembler;
  const Eigen::VectorXd u = problem.displacement(test::moderate_deformation(), 0.05, 1);

  Eigen::VectorXd gradient;
  assembler.gradient(u, gradient);
  SparseMatrix hessian = assembler.pattern();
  assembler.hessian(u, hessian);
  const Eigen::MatrixXd dense(hessian);

  const test::FiniteDifferences differences = test::central_differences(assembler, u, step);
  const Eigen::VectorXd& difference_gradient = differences.gradient;
  const Eigen::MatrixXd& difference_hessian = differences.hessian;
  EXPECT_LT((difference_gradient - gradient).norm(), 1e-6 * gradient.norm());
  EXPECT_LT((difference_hessian - dense).norm(), 1e-6 * dense.norm());
  EXPECT_LT((dense - dense.transpose()).norm(), 1e-13 * dense.norm());
  omp_set_num_threads(saved_threads);
}

TEST_P(AssemblyDerivatives, ProjectedHessianIsPositiveSemidefinite) {
  const test::AssemblyProblem problem(GetParam().type, {2, 2, 2}, GetParam().model);
  const ElasticAssembler& assembler = *problem.assembler;
  // Strong lateral compression with noise: element tangents become indefinite.
  const Eigen::Vector3d squeeze(0.6, 1.2, 1.2);
  const Eigen::VectorXd u = problem.displacement(Eigen::Matrix3d(squeeze.asDiagonal()), 0.03, 2);
  SparseMatrix hessian = assembler.pattern();

  assembler.hessian(u, hessian, false);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> raw{Eigen::MatrixXd(hessian), Eigen::EigenvaluesOnly};
  const double raw_scale = raw.eigenvalues().cwiseAbs().maxCoeff();
  // The projection has something to do: the unprojected tangent is indefinite.
  EXPECT_LT(raw.eigenvalues().minCoeff(), -1e-6 * raw_scale);

  assembler.hessian(u, hessian, true);
  const Eigen::MatrixXd dense(hessian);
  EXPECT_LT((dense - dense.transpose()).norm(), 1e-13 * dense.norm());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> projected{dense, Eigen::EigenvaluesOnly};
  EXPECT_GE(projected.eigenvalues().minCoeff(), -1e-10 * projected.eigenvalues().cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(ElasticAssembler, AssemblyDerivatives,
                         ::testing::Values(Case{ElementType::tet10, MaterialModel::stable_neo_hookean},
                                           Case{ElementType::tet10, MaterialModel::neo_hookean},
                                           Case{ElementType::hex20, MaterialModel::stable_neo_hookean},
                                           Case{ElementType::hex20, MaterialModel::neo_hookean}),
                         case_name);

}  // namespace
}  // namespace altfem
