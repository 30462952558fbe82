#pragma once
#include <memory>

#include "shared/simulation/method_instance.hpp"

namespace altfem::harmonic {

/// The `harmonic` method (Martin et al. 2008): nodal harmonic bases on the cells of a
/// polyhedral mesh, tabulated with exact-degree rules and the consistency correction
/// into the shared assembly, so every material model works.
std::unique_ptr<MethodInstance> make_harmonic_method(const Scene& scene, const SceneGeometry& geometry);
/// Its entry in the method registry: scene block and factory.
const MethodDescription& harmonic_method();

}  // namespace altfem::harmonic
