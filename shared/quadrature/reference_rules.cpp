#include "shared/quadrature/reference_rules.hpp"

#include "shared/quadrature/gauss_legendre.hpp"
#include "shared/quadrature/witherden_vincent.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace altfem {

QuadratureRule reference_rule(ReferenceDomain domain, int strength) {
  if (strength < 0) throw std::invalid_argument("quadrature strength must be >= 0, got " + std::to_string(strength));
  // The symmetric rule with the fewest points: the shipped tables and, on boxes, the
  // tensor Gauss rule (symmetric as well; ties go to the table). The collapsed simplex
  // rule is not symmetric, so it only serves strengths beyond the tables. Two tables put
  // points on the boundary (hex 3-6 at the face centres, tri 16-55 on the edges); they
  // are passed over, so that every rule served has interior points, which the embedded
  // methods rely on (a point on a face belongs to two cells).
  const bool box = domain == ReferenceDomain::quadrilateral || domain == ReferenceDomain::hexahedron;
  Eigen::Index product_point_count = box ? 1 : std::numeric_limits<Eigen::Index>::max();
  for (int d = 0; box && d < reference_dimension(domain); ++d) product_point_count *= gauss_point_count(strength);
  const QuadratureRule* smallest = nullptr;
  for (const QuadratureRule& rule : witherden_vincent_rules(domain)) {
    const Eigen::Index points = rule.weights.size();
    if (rule.strength >= strength && points <= product_point_count &&
        (!smallest || points < smallest->weights.size()) && strictly_inside(domain, rule.points))
      smallest = &rule;
  }
  if (smallest) return *smallest;
  switch (domain) {
    case ReferenceDomain::quadrilateral: return tensor_quad_rule(strength);
    case ReferenceDomain::triangle: return collapsed_triangle_rule(strength);
    case ReferenceDomain::hexahedron: return tensor_hex_rule(strength);
    case ReferenceDomain::tetrahedron: return collapsed_tet_rule(strength);
  }
  throw std::invalid_argument("reference_rule: unknown reference domain");
}

QuadratureRule hex_rule(int strength) { return reference_rule(ReferenceDomain::hexahedron, strength); }
QuadratureRule quad_rule(int strength) { return reference_rule(ReferenceDomain::quadrilateral, strength); }
QuadratureRule tet_rule(int strength) { return reference_rule(ReferenceDomain::tetrahedron, strength); }
QuadratureRule triangle_rule(int strength) { return reference_rule(ReferenceDomain::triangle, strength); }

}  // namespace altfem
