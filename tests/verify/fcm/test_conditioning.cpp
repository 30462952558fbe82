// Longva et al. 2020 §5.4, Fig. 5, on hexahedral grids: κ(SA) of A = M + Δt² K(u) as the
// smallest cut cell's volume fraction falls to 2^-30, for no preconditioner, Jacobi
// and Additive Schwarz, with and without quadrature stabilisation. Prints the table.
#include <gtest/gtest.h>

#include <cstdio>

#include "fcm/conditioning_experiment.hpp"

namespace altfem::fcm {
namespace {

void print(const char* title, const std::vector<ConditioningRow>& rows) {
  std::printf("%s\n  %12s %12s %12s %12s %6s %6s %7s\n", title, "fraction", "none", "Jacobi", "Schwarz", "CG", "J-PCG",
              "S-PCG");
  for (const auto& row : rows)
    std::printf("  %12.3e %12.3e %12.3e %12.3e %6d %6d %7d\n", row.volume_fraction, row.none, row.jacobi, row.schwarz,
                row.none_iterations, row.jacobi_iterations, row.schwarz_iterations);
}

TEST(ConditioningFigure5, Hex8) {
  const std::vector<int> exponents{0, 8, 16, 24, 30};
  const auto stabilized = conditioning_experiment(ElementType::hex8, exponents, 1e-6);
  const auto plain = conditioning_experiment(ElementType::hex8, exponents, 0.0);
  print("Hex8, stabilisation 1e-6", stabilized);
  print("Hex8, no stabilisation", plain);
  EXPECT_GT(stabilized.back().none, 1e6);
  EXPECT_LT(stabilized.back().schwarz, 1e5);
}

TEST(ConditioningFigure5, Hex20) {
  const std::vector<int> exponents{0, 16, 30};
  const auto stabilized = conditioning_experiment(ElementType::hex20, exponents, 1e-6);
  const auto plain = conditioning_experiment(ElementType::hex20, exponents, 0.0);
  print("Hex20, stabilisation 1e-6", stabilized);
  print("Hex20, no stabilisation", plain);
  EXPECT_GT(stabilized.back().none, 1e9);
  EXPECT_LT(stabilized.back().schwarz, 1e5);
  EXPECT_GT(plain.back().schwarz, 1e10);
}

// The thresholds (the authors' data at 2^-30: 1.5e10 none, 8.0e3 Jacobi,
// 1.8e4 Schwarz), on tetrahedral cells whose rules come from intersection (§4.5).
TEST(ConditioningFigure5, Tet10) {
  const std::vector<int> exponents{30};
  const auto stabilized = conditioning_experiment(ElementType::tet10, exponents, 1e-6);
  const auto plain = conditioning_experiment(ElementType::tet10, exponents, 0.0);
  print("Tet10, stabilisation 1e-6", stabilized);
  print("Tet10, no stabilisation", plain);
  EXPECT_GE(stabilized.back().none, 1e9);
  EXPECT_LE(stabilized.back().jacobi, 1e5);
  EXPECT_LE(stabilized.back().schwarz, 1e5);
  EXPECT_GE(plain.back().schwarz, 1e10);
}

}  // namespace
}  // namespace altfem::fcm
