#pragma once
// The `fcm` method (Longva et al. 2020): a Lagrange background grid over the scene's
// geometry, cut cells integrated by intersection quadrature against a tetrahedral
// mesh of the object, the embedded surface deformed through the grid's basis.
#include <memory>

#include "shared/simulation/method_instance.hpp"

namespace altfem::fcm {

std::unique_ptr<MethodInstance> make_fcm_method(const Scene& scene, const SceneGeometry& geometry);
/// Its entry in the method registry: scene block and factory.
const MethodDescription& fcm_method();

}  // namespace altfem::fcm
