// Longva et al. 2020 §5.4, Fig. 5, on hexahedral grids: κ(SA) of A = M + Δt² K(u) as the
// smallest cut cell's volume fraction falls to 2^-30, for no preconditioner, Jacobi
// and Additive Schwarz, with and without quadrature stabilisation. Prints the table.
#include <gtest/gtest.h>

#include <cstdio>

#include "fcm/conditioning_experiment.hpp"

namespace altfem::fcm {
namespace {

void print(const char* title, const std::vector<ConditioningRow>& rows) {
  std::printf("%s\n  %12s %12s %12s %12s\n", title, "fraction", "none", "Jacobi", "Schwarz");
  for (const auto& row : rows)
    std::printf("  %12.3e %12.3e %12.3e %12.3e\n", row.volume_fraction, row.none, row.jacobi, row.schwarz);
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

}  // namespace
}  // namespace altfem::fcm
