#include "shared/mesh/polyhedral_quadrature.hpp"

#include <stdexcept>

#include "shared/mesh/corner_tetrahedra.hpp"
#include "shared/quadrature/reference_rules.hpp"

namespace altfem {

QuadratureRule polyhedron_quadrature(const Polyhedron& polyhedron, int strength) {
  if (strength < 0) throw std::invalid_argument("polyhedron_quadrature: strength must be >= 0");
  const QuadratureRule reference = tet_rule(strength);  // unit tetrahedron, weights sum to 1/6
  const Eigen::Vector3d apex = polyhedron.vertices.colwise().mean().transpose();

  int triangle_count = 0;
  for (const auto& face : polyhedron.faces) {
    if (face.size() < 3) throw std::invalid_argument("polyhedron_quadrature: a face has fewer than 3 vertices");
    triangle_count += static_cast<int>(face.size()) - 2;
  }
  const Eigen::Index reference_count = reference.weights.size();
  QuadratureRule rule;
  rule.strength = reference.strength;
  rule.points.resize(triangle_count * reference_count, 3);
  rule.weights.resize(triangle_count * reference_count);
  Eigen::Index used = 0;
  for (const auto& face : polyhedron.faces) {
    const Eigen::Vector3d a = polyhedron.vertices.row(face[0]);
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
      const Eigen::Vector3d b = polyhedron.vertices.row(face[i]);
      const Eigen::Vector3d c = polyhedron.vertices.row(face[i + 1]);
      // The cone (apex, a, b, c): positive for an outward triangle seen from inside.
      const double jacobian = six_signed_volume(apex, a, b, c);
      if (jacobian == 0) continue;
      Eigen::Matrix3d map;
      map << a - apex, b - apex, c - apex;
      for (Eigen::Index q = 0; q < reference_count; ++q) {
        rule.points.row(used) = (apex + map * reference.points.row(q).transpose()).transpose();
        rule.weights(used) = jacobian * reference.weights(q);
        ++used;
      }
    }
  }
  rule.points.conservativeResize(used, 3);
  rule.weights.conservativeResize(used);
  return rule;
}

QuadratureRule cell_quadrature(const PolyhedralMesh& mesh, int cell, int strength) {
  return polyhedron_quadrature(cell_polyhedron(mesh, cell), strength);
}

}  // namespace altfem
