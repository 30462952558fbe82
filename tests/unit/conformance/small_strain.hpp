#pragma once
// The displacement gradient the conformance suite's affine fields take (test_conformance.cpp
// and test_conformance_after_a_cut.cpp): small, with every entry different, so no symmetry
// of a method's cells hides a wrong one.
#include <Eigen/Core>

namespace altfem::test {

inline Eigen::Matrix3d small_strain() {
  Eigen::Matrix3d A;
  A << 0.02, 0.01, -0.005, 0.004, -0.01, 0.006, -0.003, 0.008, 0.015;
  return A;
}

}  // namespace altfem::test
