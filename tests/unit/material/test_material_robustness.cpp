// Behaviour at det F ≤ 0 and for extreme F: defined, and never NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "shared/material/material.hpp"
#include "tests/unit/material/deformation_samples.hpp"

namespace altfem {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

template <typename Matrix>
bool all_infinite(const Matrix& m) {
  return (m.array() == infinity).all();
}

/// Singular (rank 0, 1, 2) and inverted deformations: det F ≤ 0 exactly.
std::vector<Eigen::Matrix3d> inverted_deformations() {
  std::mt19937 random(3);
  const Eigen::Matrix3d R1 = test::random_rotation(random);
  const Eigen::Matrix3d R2 = test::random_rotation(random);
  return {
      Eigen::Matrix3d::Zero(),
      Eigen::Vector3d(1.0, 0.0, 0.0).asDiagonal(),
      Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal(),
      Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal(),  // reflection: σ1 + σ2 = 0
      Eigen::Vector3d(1.0, 1.0, -1e-300).asDiagonal(),
      -Eigen::Matrix3d::Identity(),
      R1 * Eigen::Vector3d(1.3, 0.9, -0.4).asDiagonal() * R2.transpose(),
  };
}

/// Nearly singular, rotated: det F is rounding noise of either sign.
std::vector<Eigen::Matrix3d> nearly_singular_deformations() {
  std::mt19937 random(4);
  const Eigen::Matrix3d R1 = test::random_rotation(random);
  const Eigen::Matrix3d R2 = test::random_rotation(random);
  return {
      R1 * Eigen::Vector3d(2.0, 1e-9, 0.0).asDiagonal() * R2.transpose(),
      R1 * Eigen::Vector3d(1.0, 1.0, 1e-300).asDiagonal() * R2.transpose(),
      Eigen::Vector3d(1.0, 1.0, 1e-300).asDiagonal(),
      Eigen::Vector3d(1e-200, 1e-200, 1e-200).asDiagonal(),
      Eigen::Vector3d(1e200, 1e200, 1e200).asDiagonal(),
  };
}

class MaterialRobustness : public ::testing::TestWithParam<MaterialModel> {
protected:
  std::unique_ptr<Material> material = make_material(GetParam(), 1e6, 0.4, 1000.0);

  // The contract of material.hpp: energy finite or +inf; P and dP/dF entirely
  // finite or entirely +inf; nothing NaN.
  void expect_contract(const Eigen::Matrix3d& F) const {
    const double energy = material->energy(F);
    EXPECT_TRUE(std::isfinite(energy) || energy == infinity) << energy << " at F =\n" << F;
    const Eigen::Matrix3d P = material->pk1(F);
    EXPECT_TRUE(P.allFinite() || all_infinite(P)) << "P =\n" << P << "\nat F =\n" << F;
    Eigen::Matrix3d P2;
    Matrix9d dPdF;
    material->pk1_and_tangent(F, P2, dPdF);
    EXPECT_TRUE(P2.allFinite() || all_infinite(P2)) << "P =\n" << P2 << "\nat F =\n" << F;
    EXPECT_TRUE(dPdF.allFinite() || all_infinite(dPdF)) << "at F =\n" << F;
  }
};

TEST_P(MaterialRobustness, NeverNaN) {
  for (const Eigen::Matrix3d& F : inverted_deformations()) expect_contract(F);
  for (const Eigen::Matrix3d& F : nearly_singular_deformations()) expect_contract(F);
  std::mt19937 random(5);
  for (int sample = 0; sample < 2000; ++sample) {
    // Random F of every size, about half of them inverted.
    const double scale = std::pow(10.0, std::uniform_real_distribution<double>(-300.0, 300.0)(random));
    expect_contract(scale * test::random_matrix(random));
    expect_contract(test::random_matrix(random));
  }
}

TEST_P(MaterialRobustness, DefinedWhereInverted) {
  for (const Eigen::Matrix3d& F : inverted_deformations()) {
    const double energy = material->energy(F);
    Eigen::Matrix3d P;
    Matrix9d dPdF;
    material->pk1_and_tangent(F, P, dPdF);
    if (GetParam() == MaterialModel::neo_hookean) {
      // log J is undefined: +inf energy makes a line search reject the step, and
      // an all-+inf stress and tangent let the assembler name the element.
      EXPECT_EQ(energy, infinity) << "F =\n" << F;
      EXPECT_TRUE(all_infinite(material->pk1(F))) << "F =\n" << F;
      EXPECT_TRUE(all_infinite(P) && all_infinite(dPdF)) << "F =\n" << F;
    } else {
      // Every other model is defined (polynomial, or through the rotation-variant
      // SVD) for every F of moderate size.
      EXPECT_TRUE(std::isfinite(energy)) << "F =\n" << F;
      EXPECT_TRUE(material->pk1(F).allFinite()) << "F =\n" << F;
      EXPECT_TRUE(P.allFinite() && dPdF.allFinite()) << "F =\n" << F;
    }
  }
}

// Stable Neo-Hookean resists inversion: its energy grows as an element is
// pushed through J = 0, where Neo-Hookean's is already infinite.
TEST(StableNeoHookean, EnergyGrowsThroughInversion) {
  const auto material = make_material(MaterialModel::stable_neo_hookean, 1e6, 0.4, 1000.0);
  double previous = material->energy(Eigen::Matrix3d::Identity());
  for (double stretch = 0.8; stretch > -1.0; stretch -= 0.2) {
    const double energy = material->energy(Eigen::Vector3d(1.0, 1.0, stretch).asDiagonal());
    EXPECT_GT(energy, previous) << "stretch " << stretch;
    previous = energy;
  }
}

INSTANTIATE_TEST_SUITE_P(EveryModel, MaterialRobustness, ::testing::ValuesIn(all_material_models),
                         [](const auto& info) { return std::string(material_model_name(info.param)); });

}  // namespace
}  // namespace altfem
