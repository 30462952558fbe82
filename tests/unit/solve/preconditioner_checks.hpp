#pragma once
// Checks shared by the preconditioner tests.
#include <gtest/gtest.h>

#include "shared/solve/preconditioner.hpp"
#include "tests/unit/random_vectors.hpp"

namespace altfem::testing {

/// M⁻¹ of a computed preconditioner is symmetric (yᵀM⁻¹x = xᵀM⁻¹y) and positive definite
/// (xᵀM⁻¹x > 0) on `samples` pairs of random vectors of length `size`.
inline void expect_symmetric_positive_definite(const Preconditioner& preconditioner, Eigen::Index size,
                                               unsigned samples = 5) {
  Eigen::VectorXd applied_x, applied_y;
  for (unsigned seed = 1; seed <= samples; ++seed) {
    const Eigen::VectorXd x = test::random_vector(size, seed), y = test::random_vector(size, 100 + seed);
    preconditioner.apply(x, applied_x);
    preconditioner.apply(y, applied_y);
    EXPECT_NEAR(y.dot(applied_x), x.dot(applied_y), 1e-12 * x.norm() * applied_y.norm()) << "sample " << seed;
    EXPECT_GT(x.dot(applied_x), 0.0) << "sample " << seed;
  }
}

}  // namespace altfem::testing
