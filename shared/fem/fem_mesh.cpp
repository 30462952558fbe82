#include "shared/fem/fem_mesh.hpp"

#include <string>

#include "shared/common/error.hpp"
#include "shared/mesh/curve_boundary.hpp"
#include "shared/mesh/elevate_order.hpp"
#include "shared/mesh/surface_projection.hpp"
#include "shared/mesh/structured_grid.hpp"
#include "shared/mesh/tetrahedralize.hpp"

namespace altfem {

namespace {

ElementType linear_type_of(ElementType type) {
  return element_shape(type) == ElementShape::tetrahedron ? ElementType::tet4 : ElementType::hex8;
}

}  // namespace

VolumeMesh build_fem_mesh(const Scene& scene, const SceneGeometry& geometry) {
  const FemSpec& fem = scene.fem;
  const std::string file = scene.file.string();
  switch (fem.mesh) {
    case FemMeshKind::grid:
      return structured_grid(geometry.bounds, fem.resolution, fem.element);
    case FemMeshKind::tetrahedralize: {
      if (element_shape(fem.element) != ElementShape::tetrahedron)
        throw InputError(input_message(file, "/discretization/fem/element",
                                       "mesh \"tetrahedralize\" makes tetrahedra; use tet4, tet10 or tet20, got " +
                                           std::string(element_name(fem.element))));
      const double size = fem_max_cell_size(fem, geometry.bounds);
      VolumeMesh linear = geometry.surface ? tetrahedralize_surface(*geometry.surface, size)
                                           : tetrahedralize_shape(*geometry.shape, size);
      VolumeMesh mesh = elevate_order(linear, fem.element);
      if (fem.curved && fem.element != ElementType::tet4) {
        if (geometry.surface) {
          const SurfaceProjection projection(*geometry.surface);
          curve_boundary(mesh, [&](const Eigen::Vector3d& x) { return projection.closest_point(x); });
        } else {
          const double step = 1e-7 * geometry.bounds.diagonal().norm();
          const auto level_set = [&](const Eigen::Vector3d& x) { return geometry.shape->level_set(x); };
          curve_boundary(mesh, [&](const Eigen::Vector3d& x) { return project_to_level_set(level_set, x, step); });
        }
      }
      return mesh;
    }
    case FemMeshKind::file: {
      const VolumeMesh& mesh = *geometry.mesh;
      if (mesh.element_type == fem.element) return mesh;
      if (mesh.element_type == linear_type_of(fem.element)) return elevate_order(mesh, fem.element);
      throw InputError(input_message(file, "/discretization/fem/element",
                                     "the mesh file has " + std::string(element_name(mesh.element_type)) +
                                         " cells, which cannot be turned into " +
                                         std::string(element_name(fem.element))));
    }
  }
  throw InputError(input_message(file, "/discretization/fem/mesh", "unknown mesh kind"));
}

}  // namespace altfem
