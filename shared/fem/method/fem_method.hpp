#pragma once
#include <memory>

#include "shared/simulation/method_instance.hpp"

namespace altfem {

/// The `fem` method: conforming Lagrange elements on the mesh of build_fem_mesh.
std::unique_ptr<MethodInstance> make_fem_method(const Scene& scene, const SceneGeometry& geometry);
/// Its entry in the method registry: scene block and factory.
const MethodDescription& fem_method();

}  // namespace altfem
