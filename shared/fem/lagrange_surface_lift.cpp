#include "shared/fem/lagrange_surface_lift.hpp"

#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "shared/element/geometry_map.hpp"

namespace altfem {

namespace {

struct LiftedTriangle {
  Eigen::MatrixXd cell_nodes;  // #nodes × 3
  Eigen::Matrix3d corners;     // row i: the reference point of the triangle's corner i
};

}  // namespace

SurfaceLift lagrange_surface_lift(const VolumeMesh& mesh, const BoundarySurface& boundary) {
  const ReferenceElement& element = reference_element(mesh.element_type);
  auto triangles = std::make_shared<std::vector<LiftedTriangle>>(boundary.surface.triangles.rows());
  for (Eigen::Index t = 0; t < boundary.surface.triangles.rows(); ++t) {
    const int cell = boundary.cells[t];
    LiftedTriangle& lifted = (*triangles)[t];
    lifted.cell_nodes.resize(element.node_count(), 3);
    for (int k = 0; k < element.node_count(); ++k) lifted.cell_nodes.row(k) = mesh.nodes.row(mesh.cells(cell, k));
    for (int corner = 0; corner < 3; ++corner) {
      const int node = boundary.mesh_nodes[boundary.surface.triangles(t, corner)];
      for (int k = 0; k < element.node_count(); ++k)
        if (mesh.cells(cell, k) == node) lifted.corners.row(corner) = element.nodes().row(k);
    }
  }
  return [&element, triangles](int triangle, const Eigen::Vector3d& barycentric, Eigen::Vector3d& point,
                               Eigen::Vector3d& area_vector) {
    const LiftedTriangle& lifted = (*triangles)[triangle];
    const Eigen::Vector3d xi = lifted.corners.transpose() * barycentric;
    point = map_to_physical(element, lifted.cell_nodes, xi);
    const Eigen::Matrix3d jacobian = map_jacobian(element, lifted.cell_nodes, xi);
    const Eigen::Vector3d tangent1 = jacobian * (lifted.corners.row(1) - lifted.corners.row(0)).transpose();
    const Eigen::Vector3d tangent2 = jacobian * (lifted.corners.row(2) - lifted.corners.row(0)).transpose();
    area_vector = tangent1.cross(tangent2);
  };
}

}  // namespace altfem
