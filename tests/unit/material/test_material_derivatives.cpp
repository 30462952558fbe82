// PK1 against central differences of the energy and dP/dF against central
// differences of PK1, for every model, near and far from the identity.
#include <gtest/gtest.h>

#include "shared/material/material.hpp"
#include "tests/unit/material/deformation_samples.hpp"

namespace altfem {
namespace {

constexpr double tolerance = 1e-6;

std::vector<Eigen::Matrix3d> samples(MaterialModel model) {
  std::mt19937 random(20240611);
  std::vector<Eigen::Matrix3d> result = test::random_deformations(random, 6, 0.1);
  const std::vector<Eigen::Matrix3d> far = test::random_deformations(random, 6, 0.6);
  result.insert(result.end(), far.begin(), far.end());
  const Eigen::Matrix3d R1 = test::random_rotation(random);
  const Eigen::Matrix3d R2 = test::random_rotation(random);
  // Large stretch, and (nearly) repeated singular values, where an SVD basis is
  // not unique but R and ψ are smooth.
  result.push_back(R1 * Eigen::Vector3d(2.5, 0.4, 1.3).asDiagonal() * R2.transpose());
  result.push_back(R1 * Eigen::Vector3d(1.1, 1.1 + 1e-10, 0.8).asDiagonal() * R2.transpose());
  result.push_back(1.2 * R1);
  // Inverted (det F < 0): the models defined there must be differentiable too.
  if (model != MaterialModel::neo_hookean) {
    result.push_back(R1 * Eigen::Vector3d(1.3, 0.9, -0.4).asDiagonal() * R2.transpose());
    result.push_back(R2 * Eigen::Vector3d(0.7, 0.6, -0.2).asDiagonal() * R1.transpose());
  }
  return result;
}

class MaterialDerivatives : public ::testing::TestWithParam<MaterialModel> {
protected:
  std::unique_ptr<Material> material = make_material(GetParam(), 1e6, 0.45, 1000.0);
};

TEST_P(MaterialDerivatives, Pk1IsTheEnergyGradient) {
  for (const Eigen::Matrix3d& F : samples(GetParam())) {
    const Eigen::Matrix3d P = material->pk1(F);
    const Eigen::Matrix3d expected =
        test::finite_difference_gradient([&](const Eigen::Matrix3d& G) { return material->energy(G); }, F, 1e-6);
    EXPECT_LE((P - expected).norm(), tolerance * expected.norm()) << "F =\n" << F << "\nP =\n" << P;
  }
}

TEST_P(MaterialDerivatives, TangentIsThePk1Jacobian) {
  for (const Eigen::Matrix3d& F : samples(GetParam())) {
    Eigen::Matrix3d P;
    Matrix9d dPdF;
    material->pk1_and_tangent(F, P, dPdF);
    const Matrix9d expected =
        test::finite_difference_jacobian([&](const Eigen::Matrix3d& G) { return material->pk1(G); }, F, 1e-6);
    EXPECT_LE((dPdF - expected).norm(), tolerance * expected.norm()) << "F =\n" << F;
    // A hyperelastic tangent is a Hessian: symmetric.
    EXPECT_LE((dPdF - dPdF.transpose()).norm(), 1e-12 * dPdF.norm()) << "F =\n" << F;
    // The combined call returns the same stress as pk1().
    EXPECT_LE((P - material->pk1(F)).norm(), 1e-14 * P.norm()) << "F =\n" << F;
  }
}

INSTANTIATE_TEST_SUITE_P(EveryModel, MaterialDerivatives, ::testing::ValuesIn(all_material_models),
                         [](const auto& info) { return std::string(material_model_name(info.param)); });

}  // namespace
}  // namespace altfem
