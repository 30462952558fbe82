#pragma once
// The `dg` method (Kaufmann et al. 2009): interior-penalty or Babuška–Zlámal DG with
// monomials of degree 1–3 on the polyhedra of a converted tetrahedral or hexahedral mesh,
// every volume and face integral exact (§4, §5), Dirichlet conditions imposed weakly
// (§4.2), the scene surface embedded by stitching (§7, eq. (30)). The linear material
// uses the exact matrices (LinearDgDiscretization); any other model the shared assembly
// at polyhedron rules with the Babuška–Zlámal flux (tabulated_dg.hpp).
#include <memory>

#include "shared/simulation/method_instance.hpp"

namespace altfem::dg {

std::unique_ptr<MethodInstance> make_dg_method(const Scene& scene, const SceneGeometry& geometry);
/// Its entry in the method registry: scene block and factory.
const MethodDescription& dg_method();

}  // namespace altfem::dg
