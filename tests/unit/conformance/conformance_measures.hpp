#pragma once
// What the conformance suite measures a method by, before a cut (test_conformance.cpp) and
// after one (test_conformance_after_a_cut.cpp).
#include <Eigen/Core>

#include "shared/simulation/method_instance.hpp"

namespace altfem::test {

// The displacement gradient of the suite's affine fields: small, with every entry
// different, so no symmetry of a method's cells hides a wrong one.
inline Eigen::Matrix3d small_strain() {
  Eigen::Matrix3d A;
  A << 0.02, 0.01, -0.005, 0.004, -0.01, 0.006, -0.003, 0.008, 0.015;
  return A;
}

// The volume `method` integrates: ∫ρ·1 / ρ through its load vector.
inline double integrated_volume(const MethodInstance& method, double density) {
  const Eigen::VectorXd ones =
      method.interpolate([](const Eigen::Vector3d&) { return Eigen::Vector3d::Ones().eval(); });
  return ones.dot(method.discretization().body_force(Eigen::Vector3d::UnitX())) / density;
}

// The internal force of `method` at the displacement `u`.
inline Eigen::VectorXd internal_force(const MethodInstance& method, const Eigen::VectorXd& u) {
  Eigen::VectorXd g;
  method.discretization().gradient(u, g);
  return g;
}

}  // namespace altfem::test
