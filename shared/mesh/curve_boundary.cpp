#include "shared/mesh/curve_boundary.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <stdexcept>
#include <vector>

#include "shared/element/geometry_map.hpp"
#include "shared/element/reference_element.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/quadrature/reference_rules.hpp"

namespace altfem {

int curve_boundary(VolumeMesh& mesh, const ClosestPoint& closest_point) {
  if (element_shape(mesh.element_type) != ElementShape::tetrahedron)
    throw std::invalid_argument("curve_boundary: tetrahedral meshes only");
  const ReferenceElement& element = reference_element(mesh.element_type);
  const ReferenceElement& linear = reference_element(ElementType::tet4);
  const int nodes = element.node_count();

  // Which corners each higher-order node interpolates (non-zero linear weight).
  std::vector<std::vector<int>> corners_of(nodes);
  Eigen::VectorXd weights(4);
  for (int j = 4; j < nodes; ++j) {
    linear.evaluate(element.nodes().row(j).transpose(), weights);
    for (int k = 0; k < 4; ++k)
      if (std::abs(weights[k]) > 1e-12) corners_of[j].push_back(k);
  }

  // A node is on a boundary face when all its corners are corners of that face.
  const BoundarySurface boundary = boundary_surface(mesh);
  std::vector<char> on_boundary(mesh.nodes.rows(), 0);
  for (Eigen::Index t = 0; t < boundary.surface.triangles.rows(); ++t) {
    const int cell = boundary.cells[t];
    int face[3];
    for (int c = 0; c < 3; ++c) face[c] = boundary.mesh_nodes[boundary.surface.triangles(t, c)];
    for (int j = 4; j < nodes; ++j) {
      const bool on_face = std::all_of(corners_of[j].begin(), corners_of[j].end(), [&](int k) {
        return std::find(face, face + 3, mesh.cells(cell, k)) != face + 3;
      });
      if (on_face) on_boundary[mesh.cells(cell, j)] = 1;
    }
  }
  const Eigen::MatrixXd straight = mesh.nodes;
  for (Eigen::Index node = 0; node < mesh.nodes.rows(); ++node)
    if (on_boundary[node]) mesh.nodes.row(node) = closest_point(mesh.nodes.row(node).transpose()).transpose();

  // Where the true surface bends more than a cell can follow (a coarse cell on a
  // thin feature), the moved nodes fold the cell: such cells keep straight edges.
  // A cell is kept curved while det J at its nodes stays above a fifth of its
  // straight (constant) value.
  const QuadratureRule rule = tet_rule(4);
  Eigen::MatrixXd cell_nodes(nodes, 3), straight_nodes(nodes, 3);
  for (int pass = 0; pass < 10; ++pass) {
    bool restored = false;
    for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell) {
      bool curved = false;
      for (int a = 0; a < nodes; ++a) {
        cell_nodes.row(a) = mesh.nodes.row(mesh.cells(cell, a));
        straight_nodes.row(a) = straight.row(mesh.cells(cell, a));
        curved = curved || on_boundary[mesh.cells(cell, a)];
      }
      if (!curved) continue;
      const double reference = map_jacobian(element, straight_nodes, element.centroid()).determinant();
      bool folded = false;
      for (int q = 0; q < rule.points.rows() && !folded; ++q)
        folded = map_jacobian(element, cell_nodes, rule.points.row(q).transpose()).determinant() < 0.2 * reference;
      for (int a = 0; a < nodes && !folded; ++a)
        folded = map_jacobian(element, cell_nodes, element.nodes().row(a).transpose()).determinant() < 0.2 * reference;
      if (!folded) continue;
      for (int a = 0; a < nodes; ++a) {
        const int node = mesh.cells(cell, a);
        if (on_boundary[node]) {
          mesh.nodes.row(node) = straight.row(node);
          on_boundary[node] = 0;
          restored = true;
        }
      }
    }
    if (!restored) break;
  }
  return static_cast<int>(std::count(on_boundary.begin(), on_boundary.end(), 1));
}

Eigen::Vector3d project_to_level_set(const std::function<double(const Eigen::Vector3d&)>& level_set,
                                     const Eigen::Vector3d& x, double step) {
  Eigen::Vector3d point = x;
  for (int iteration = 0; iteration < 20; ++iteration) {
    const double value = level_set(point);
    Eigen::Vector3d gradient;
    for (int d = 0; d < 3; ++d) {
      Eigen::Vector3d forward = point, backward = point;
      forward[d] += step;
      backward[d] -= step;
      gradient[d] = (level_set(forward) - level_set(backward)) / (2 * step);
    }
    const double norm = gradient.squaredNorm();
    if (!(norm > 0)) break;
    const Eigen::Vector3d correction = value / norm * gradient;
    point -= correction;
    if (correction.norm() <= 1e-3 * step) break;
  }
  return point;
}

}  // namespace altfem
