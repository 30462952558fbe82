// Rest and rigid motions are stress free, and every model is linear elasticity
// at small strain.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shared/material/material.hpp"
#include "tests/unit/material/deformation_samples.hpp"

namespace altfem {
namespace {

constexpr double youngs_modulus = 1e9;

class MaterialRestState : public ::testing::TestWithParam<MaterialModel> {
protected:
  std::unique_ptr<Material> material = make_material(GetParam(), youngs_modulus, 0.3, 1000.0);
  std::unique_ptr<Material> linear = make_material(MaterialModel::linear, youngs_modulus, 0.3, 1000.0);
};

TEST_P(MaterialRestState, StressFreeAtRest) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  EXPECT_NEAR(material->energy(I), 0.0, 1e-15 * youngs_modulus);
  EXPECT_LE(material->pk1(I).norm(), 1e-15 * youngs_modulus);
}

TEST_P(MaterialRestState, StressFreeUnderRigidRotation) {
  if (GetParam() == MaterialModel::linear) {
    // Linear elasticity is not rotation invariant: a quarter turn stresses it.
    const Eigen::Matrix3d quarter_turn = Eigen::AngleAxisd(EIGEN_PI / 2, Eigen::Vector3d::UnitZ()).matrix();
    EXPECT_GT(material->pk1(quarter_turn).norm(), 0.1 * youngs_modulus);
    return;
  }
  std::mt19937 random(7);
  for (int sample = 0; sample < 20; ++sample) {
    const Eigen::Matrix3d R = test::random_rotation(random);
    EXPECT_NEAR(material->energy(R), 0.0, 1e-13 * youngs_modulus) << "R =\n" << R;
    EXPECT_LE(material->pk1(R).norm(), 1e-13 * youngs_modulus) << "R =\n" << R;
  }
}

// F = I + H, H = 1e-6 G: P agrees with linear elasticity's up to second-order
// terms, C·E·‖H‖² = O(1e-12 E) (measured C ≤ 2.6, for stable Neo-Hookean); a
// wrong small-strain modulus would show at O(1e-6 E).
TEST_P(MaterialRestState, MatchesLinearElasticityAtSmallStrain) {
  std::mt19937 random(11);
  for (int sample = 0; sample < 20; ++sample) {
    const Eigen::Matrix3d H = 1e-6 * test::random_matrix(random);
    const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + H;
    const Eigen::Matrix3d expected = linear->pk1(F);
    EXPECT_GT(expected.norm(), 1e-8 * youngs_modulus);
    EXPECT_LE((material->pk1(F) - expected).norm(), 4.0 * youngs_modulus * H.squaredNorm()) << "F =\n" << F;
  }
}

// The models written in the displacement gradient G (all but corotated_linear, which forms
// F = I + G for its polar decomposition): at G of 1e-11 (a 1 µm cube under gravity), where
// F = I + G keeps 5 digits of G, their stress and energy are linear elasticity's to its
// O(|G|) nonlinearity, 1e-9 relative (issue #35).
TEST(SmallStrainMaterials, DisplacementGradientFormsKeepTinyStrainsDigits) {
  const LameParameters lame = make_material(MaterialModel::linear, youngs_modulus, 0.3, 1000.0)->lame();
  for (const MaterialModel model : {MaterialModel::linear, MaterialModel::neo_hookean,
                                    MaterialModel::stable_neo_hookean, MaterialModel::st_venant_kirchhoff}) {
    SCOPED_TRACE(material_model_name(model));
    const auto material = make_material(model, youngs_modulus, 0.3, 1000.0);
    std::mt19937 random(13);
    for (int sample = 0; sample < 20; ++sample) {
      const Eigen::Matrix3d G = 1e-11 * test::random_matrix(random);
      const Eigen::Matrix3d symmetric = 0.5 * (G + G.transpose());
      const Eigen::Matrix3d expected =
          2 * lame.mu * symmetric + lame.lambda * symmetric.trace() * Eigen::Matrix3d::Identity();
      EXPECT_LE((material->pk1_at(G) - expected).norm(), 1e-9 * expected.norm());
      Eigen::Matrix3d P;
      Matrix9d dPdF;
      material->pk1_and_tangent_at(G, P, dPdF);
      EXPECT_LE((P - expected).norm(), 1e-9 * expected.norm());
      const double energy = lame.mu * symmetric.squaredNorm() + 0.5 * lame.lambda * std::pow(symmetric.trace(), 2);
      EXPECT_NEAR(material->energy_at(G), energy, 1e-8 * energy);
    }
  }
}

// The energies in G are the textbooks' formulas in F where F holds all the digits (|G| of
// 0.3): Neo-Hookean (Bonet & Wood), Stable Neo-Hookean (Smith et al. 2018, with its Lamé
// mapping and rest-state shift) and St. Venant–Kirchhoff, each written here from F.
TEST(SmallStrainMaterials, EnergiesInTheDisplacementGradientAreTheTextbooksFormulas) {
  const LameParameters lame = make_material(MaterialModel::linear, youngs_modulus, 0.3, 1000.0)->lame();
  const auto neo_hookean = make_material(MaterialModel::neo_hookean, youngs_modulus, 0.3, 1000.0);
  const auto stable = make_material(MaterialModel::stable_neo_hookean, youngs_modulus, 0.3, 1000.0);
  const auto kirchhoff = make_material(MaterialModel::st_venant_kirchhoff, youngs_modulus, 0.3, 1000.0);
  const double mu = 4.0 / 3.0 * lame.mu, lambda = lame.lambda + 5.0 / 6.0 * lame.mu, alpha = 1 + 0.75 * mu / lambda;
  const auto stable_energy = [&](const Eigen::Matrix3d& F) {
    return 0.5 * mu * (F.squaredNorm() - 3) + 0.5 * lambda * std::pow(F.determinant() - alpha, 2) -
           0.5 * mu * std::log(F.squaredNorm() + 1);
  };
  const double rest = stable_energy(Eigen::Matrix3d::Identity());
  std::mt19937 random(17);
  for (int sample = 0; sample < 20; ++sample) {
    const Eigen::Matrix3d G = 0.3 * test::random_matrix(random);
    const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + G;
    const double log_J = std::log(F.determinant());
    const double expected_neo_hookean =
        0.5 * lame.mu * (F.squaredNorm() - 3) - lame.mu * log_J + 0.5 * lame.lambda * log_J * log_J;
    EXPECT_NEAR(neo_hookean->energy_at(G), expected_neo_hookean, 1e-12 * youngs_modulus);
    const double expected_stable = stable_energy(F) - rest;
    EXPECT_NEAR(stable->energy_at(G), expected_stable, 1e-12 * youngs_modulus);
    const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
    const double expected_kirchhoff = lame.mu * E.squaredNorm() + 0.5 * lame.lambda * std::pow(E.trace(), 2);
    EXPECT_NEAR(kirchhoff->energy_at(G), expected_kirchhoff, 1e-12 * youngs_modulus);
  }
}

// At F = I every tangent equals linear elasticity's μ(δik δjl + δil δjk) + λ δij δkl.
TEST_P(MaterialRestState, TangentAtRestIsLinearElasticity) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d P, P_linear;
  Matrix9d dPdF, expected;
  material->pk1_and_tangent(I, P, dPdF);
  linear->pk1_and_tangent(I, P_linear, expected);
  EXPECT_LE((dPdF - expected).norm(), 1e-12 * expected.norm()) << "dPdF =\n" << dPdF;
}

INSTANTIATE_TEST_SUITE_P(EveryModel, MaterialRestState, ::testing::ValuesIn(all_material_models),
                         [](const auto& info) { return std::string(material_model_name(info.param)); });

}  // namespace
}  // namespace altfem
