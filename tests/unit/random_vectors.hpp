#pragma once
// Reproducible random test data shared by the unit test areas.
#include <Eigen/Core>
#include <random>

namespace altfem::test {

/// `size` entries uniform in [−1, 1] from a seeded generator.
inline Eigen::VectorXd random_vector(Eigen::Index size, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd v(size);
  for (auto& value : v) value = uniform(random);
  return v;
}

}  // namespace altfem::test
