// Longva et al. 2020, §4.6, Fig. 4: for m = 1..10 on every background cell type, the
// simplified rule of an embedded, rotated cuboid integrates every monomial of degree
// <= m to 1e-11 and within 100× of the initial rule, with at most M positive weights,
// all points inside the cuboid. Prints the table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "fcm/monomial_experiment.hpp"
#include "simplification_methods.hpp"

namespace altfem::fcm {
namespace {

class MonomialFigure : public ::testing::TestWithParam<SimplificationMethod> {};

TEST_P(MonomialFigure, SimplifiedRulesAreAsExactAsTheInitialOnes) {
  std::printf("%-6s %2s %4s %8s %6s %10s %10s %10s\n", "cell", "m", "M", "initial", "final", "init max", "simp max",
              "min w");
  for (const ElementType cell :
       {ElementType::hex8, ElementType::hex20, ElementType::hex27, ElementType::tet4, ElementType::tet10}) {
    for (int m = 1; m <= 10; ++m) {
      const MonomialExperiment e = run_monomial_experiment(cell, m, GetParam());
      std::printf("%-6s %2d %4d %8lld %6lld %10.2e %10.2e %10.2e\n", std::string(element_name(cell)).c_str(), m,
                  e.basis_size, static_cast<long long>(e.initial.points), static_cast<long long>(e.simplified.points),
                  e.initial.max_relative_error, e.simplified.max_relative_error, e.simplified.min_weight);
      SCOPED_TRACE(std::string(element_name(cell)) + " m = " + std::to_string(m));
      EXPECT_FALSE(e.simplification_failed);
      EXPECT_LE(e.initial.max_relative_error, 1e-13);
      EXPECT_LE(e.simplified.max_relative_error, 1e-11);
      EXPECT_LE(e.simplified.max_relative_error, 100.0 * std::max(e.initial.max_relative_error, 1e-16));
      EXPECT_LE(e.simplified.points, e.basis_size);
      EXPECT_GT(e.simplified.min_weight, 0.0);
      EXPECT_TRUE(e.initial.inside);
      EXPECT_TRUE(e.simplified.inside);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, MonomialFigure, testing::every_simplification_method(),
                         testing::simplification_method_test_name);

}  // namespace
}  // namespace altfem::fcm
