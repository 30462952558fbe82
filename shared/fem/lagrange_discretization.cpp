#include "shared/fem/lagrange_discretization.hpp"

#include "shared/fem/first_order_space.hpp"
#include "shared/fem/nodal_dirichlet.hpp"
#include "shared/fem/tabulate_lagrange.hpp"
#include "shared/quadrature/reference_rules.hpp"

namespace altfem {

std::unique_ptr<TabulatedDiscretization> make_lagrange_discretization(const VolumeMesh& mesh, const Material& material,
                                                                      const std::vector<DirichletCondition>& dirichlet,
                                                                      int quadrature_strength,
                                                                      const std::string& scene_file) {
  return make_lagrange_discretization(mesh, {&material}, {}, dirichlet, quadrature_strength, scene_file);
}

std::unique_ptr<TabulatedDiscretization> make_lagrange_discretization(
    const VolumeMesh& mesh, std::vector<const Material*> materials, std::vector<int> material_ids,
    const std::vector<DirichletCondition>& dirichlet, int quadrature_strength, const std::string& scene_file,
    const NodeConstraints* constraints) {
  const bool tetrahedra = element_shape(mesh.element_type) == ElementShape::tetrahedron;
  DiscretizationParts parts;
  LagrangeCellRules rules{
      tetrahedra ? tet_rule(quadrature_strength) : hex_rule(quadrature_strength), {}, std::move(material_ids)};
  parts.materials = std::move(materials);
  const bool hanging = constraints && !constraints->empty();
  // Each rank tabulates only its cells (the discretization is built below, while `mesh`
  // and `constraints` live).
  parts.tabulate = lagrange_tabulator(mesh, std::move(rules), constraints);
  parts.dirichlet = nodal_dirichlet(mesh.nodes.topRows(hanging ? constraints->free_nodes : mesh.nodes.rows()),
                                    dirichlet, scene_file, "the fem mesh");
  parts.coarse_space = first_order_space(mesh, constraints);
  // Gentle coarsening of the first-order level: the cantilever's Tet10 took 24 and 19 CG
  // iterations against 39 and 30 (20 × 2 × 2, 40 × 4 × 4), Hex20 17 and 16 against 29 and
  // 23, in as much time or less (docs/performance.md). fcm keeps the default: its cut
  // cells, not the coarse level, set its count (the half-ball's 105 either way).
  parts.coarse_space.coarsen_gently = true;
  return std::make_unique<TabulatedDiscretization>(std::move(parts));
}

}  // namespace altfem
