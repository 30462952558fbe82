#pragma once
#include <memory>
#include <string>
#include <vector>

#include "shared/assembly/tabulated_discretization.hpp"
#include "shared/mesh/node_constraints.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/scene/scene.hpp"

namespace altfem {

/// The conforming discretization of a Lagrange mesh, the whole of `fem`: every cell
/// tabulated with the reference rule of `quadrature_strength` (material 0), nodal
/// Dirichlet conditions, lumped explicit mass. The FCM composes the same parts
/// (tabulate_lagrange with its cut-cell rules, nodal_dirichlet on its background nodes)
/// itself. `material` must outlive the result; `mesh` need not.
std::unique_ptr<TabulatedDiscretization> make_lagrange_discretization(const VolumeMesh& mesh, const Material& material,
                                                                      const std::vector<DirichletCondition>& dirichlet,
                                                                      int quadrature_strength,
                                                                      const std::string& scene_file = "scene");
/// The same with several materials: material_ids holds each cell's index into
/// `materials` (empty: all 0); with `constraints` (not null), on the free nodes only, hanging
/// nodes' functions handed to their masters (tabulate_lagrange) — a hanging node
/// on a Dirichlet region lies on its coarse neighbour's face there, whose nodes hold it.
std::unique_ptr<TabulatedDiscretization> make_lagrange_discretization(
    const VolumeMesh& mesh, std::vector<const Material*> materials, std::vector<int> material_ids,
    const std::vector<DirichletCondition>& dirichlet, int quadrature_strength, const std::string& scene_file = "scene",
    const NodeConstraints* constraints = nullptr);

}  // namespace altfem
