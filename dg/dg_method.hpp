#pragma once
// The `dg` method (Kaufmann et al. 2009): interior-penalty or Babuška–Zlámal DG with
// monomials of degree 1–3 on the polyhedra of a converted tetrahedral or hexahedral mesh,
// every volume and face integral exact (§4, §5), Dirichlet conditions imposed weakly
// (§4.2), the scene surface embedded by stitching (§7, eq. (30)). Linear elasticity
// only in this build: any other material model is bad input.
#include <memory>

#include "shared/simulation/method_instance.hpp"

namespace altfem::dg {

std::unique_ptr<MethodInstance> make_dg_method(const Scene& scene, const SceneGeometry& geometry);
/// Its entry in the method registry: scene block and factory.
const MethodDescription& dg_method();

}  // namespace altfem::dg
