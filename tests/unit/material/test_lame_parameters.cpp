#include "shared/material/lame_parameters.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "shared/common/error.hpp"
#include "shared/material/material.hpp"

namespace altfem {
namespace {

void expect_relative(double actual, double expected, double tolerance = 1e-13) {
  EXPECT_NEAR(actual, expected, tolerance * std::abs(expected)) << "expected " << expected;
}

TEST(LameParameters, TextbookValues) {
  // E = 1 GPa, ν = 0.3: λ = 0.3/(1.3 · 0.4) GPa = 7.5/13 GPa, μ = 1/2.6 GPa = 5/13 GPa.
  const LameParameters a = lame_parameters(1e9, 0.3);
  expect_relative(a.lambda, 576923076.92307692);
  expect_relative(a.mu, 384615384.61538462);
  // Structural steel, E = 210 GPa, ν = 0.3.
  const LameParameters steel = lame_parameters(210e9, 0.3);
  expect_relative(steel.lambda, 121153846153.84615);
  expect_relative(steel.mu, 80769230769.230769);
  // Nearly incompressible rubber-like ν = 0.49: λ/μ = 2ν/(1 − 2ν) = 49.
  const LameParameters rubber = lame_parameters(1e6, 0.49);
  expect_relative(rubber.lambda, 1e6 * 0.49 / (1.49 * 0.02));
  expect_relative(rubber.mu, 1e6 / 2.98);
  expect_relative(rubber.lambda / rubber.mu, 49.0, 1e-12);
}

// The FCM paper's errata traces its results to λ off by a factor 4. Check the
// parameters through the physics they must reproduce, not through the formula:
// a linear material under uniaxial stress σ has strain σ/E along the load and
// −νσ/E across it, and its bulk modulus is E/(3(1 − 2ν)).
TEST(LameParameters, ReproduceUniaxialStressAndBulkModulus) {
  for (const double nu : {0.0, 0.25, 0.3, 0.45, 0.49, -0.3}) {
    const double E = 2.5e7;
    const auto material = make_material(MaterialModel::linear, E, nu, 1000.0);
    const double strain = 1e-3;
    const Eigen::Matrix3d F = Eigen::Vector3d(1.0 + strain, 1.0 - nu * strain, 1.0 - nu * strain).asDiagonal();
    const Eigen::Matrix3d P = material->pk1(F);
    EXPECT_NEAR(P(0, 0), E * strain, 1e-10 * E * strain) << "nu = " << nu;
    EXPECT_NEAR(P(1, 1), 0.0, 1e-10 * E * strain) << "nu = " << nu;
    EXPECT_NEAR(P(2, 2), 0.0, 1e-10 * E * strain) << "nu = " << nu;

    const LameParameters lame = material->lame();
    expect_relative(lame.lambda + 2.0 * lame.mu / 3.0, E / (3.0 * (1.0 - 2.0 * nu)), 1e-12);
  }
}

TEST(LameParameters, RejectsOutOfRangeInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(lame_parameters(0.0, 0.3), InputError);
  EXPECT_THROW(lame_parameters(-1e6, 0.3), InputError);
  EXPECT_THROW(lame_parameters(nan, 0.3), InputError);
  EXPECT_THROW(lame_parameters(std::numeric_limits<double>::infinity(), 0.3), InputError);
  EXPECT_THROW(lame_parameters(1e6, 0.5), InputError);
  EXPECT_THROW(lame_parameters(1e6, -1.0), InputError);
  EXPECT_THROW(lame_parameters(1e6, nan), InputError);
  try {
    lame_parameters(1e6, 0.5);
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("poisson_ratio"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("got 0.5"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace altfem
