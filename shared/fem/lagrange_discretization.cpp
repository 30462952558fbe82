#include "shared/fem/lagrange_discretization.hpp"

#include "shared/fem/nodal_dirichlet.hpp"
#include "shared/fem/tabulate_lagrange.hpp"

namespace altfem {

std::unique_ptr<TabulatedDiscretization> make_lagrange_discretization(
    const VolumeMesh& mesh, const Material& material, const std::vector<DirichletCondition>& dirichlet,
    int quadrature_strength, const std::string& scene_file) {
  DiscretizationParts parts;
  parts.elements = tabulate_lagrange(mesh, quadrature_strength);
  parts.materials = {&material};
  parts.dirichlet = nodal_dirichlet(mesh.nodes, dirichlet, scene_file, "the fem mesh");
  return std::make_unique<TabulatedDiscretization>(std::move(parts));
}

}  // namespace altfem
