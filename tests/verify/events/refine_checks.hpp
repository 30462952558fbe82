#pragma once
// What the refine tests of fem and fcm check alike: the patch test's affine field on the
// 1 × 0.1 × 0.1 m cantilever (E = 1e8 Pa, ν = 0.3) and its exact energy, and a refine event
// refused before the run.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <string>

#include "app/method_registry.hpp"
#include "shared/common/error.hpp"
#include "shared/scene/scene_geometry.hpp"
#include "shared/simulation/simulation.hpp"

namespace altfem {

/// The affine displacement the patch tests carry across a refinement: u = G x.
inline Eigen::Matrix3d patch_gradient() {
  Eigen::Matrix3d gradient;
  gradient << 1e-3, 0, 2e-4, 3e-4, -1e-4, 0, -2e-4, 0, 5e-4;
  return gradient;
}
inline Eigen::Vector3d patch_field(const Eigen::Vector3d& x) { return patch_gradient() * x; }

/// Its strain energy on the cantilever: ½ ε:C:ε × 0.01 m³, ε the symmetric part of G.
inline double patch_energy() {
  const Eigen::Matrix3d strain = 0.5 * (patch_gradient() + patch_gradient().transpose());
  const double E = 1e8, nu = 0.3, lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  return (0.5 * lambda * strain.trace() * strain.trace() + mu * strain.squaredNorm()) * 0.01;
}

/// A refine event the method refuses before the run (MethodInstance::refine_refusal):
/// building its Simulation throws an InputError naming the event and saying `why`.
inline void expect_refine_refused(const Scene& scene, const std::string& method_name, const std::string& why) {
  const SceneGeometry geometry = load_scene_geometry(scene);
  const MethodDescription& method = cli::find_method(method_name);
  try {
    Simulation simulation(scene, geometry, method_name, method.factory, method.rebuild);
    ADD_FAILURE() << method_name << " refined: " << why;
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/events/0/refine: cannot refine with " + method_name + ": " + why),
              std::string::npos)
        << error.what();
  }
}

}  // namespace altfem
