#pragma once
// The simplifiers the parameterised verify tests run, each test named after its method.
#include <gtest/gtest.h>

#include <string>

#include "shared/quadrature/simplify_quadrature.hpp"

namespace altfem::fcm::testing {

/// lp, nnls and caratheodory, for INSTANTIATE_TEST_SUITE_P.
inline auto every_simplification_method() {
  return ::testing::Values(SimplificationMethod::linear_program, SimplificationMethod::nonnegative_least_squares,
                           SimplificationMethod::caratheodory);
}

/// "lp", "nnls" or "caratheodory": the test name suffix.
inline std::string simplification_method_test_name(const ::testing::TestParamInfo<SimplificationMethod>& info) {
  return std::string(simplification_method_name(info.param));
}

}  // namespace altfem::fcm::testing
