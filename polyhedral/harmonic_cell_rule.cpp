#include "polyhedral/harmonic_cell_rule.hpp"

#include "shared/quadrature/polyhedron_monte_carlo_rule.hpp"
#include "shared/quadrature/polyhedron_subdivision_rule.hpp"

namespace altfem::harmonic {

PolyhedronRule harmonic_cell_rule(const Polyhedron& polyhedron, int strength, const HarmonicQuadrature& quadrature,
                                  std::uint64_t seed) {
  switch (quadrature.kind) {
    case HarmonicRuleKind::subdivision:
      return polyhedron_subdivision_rule(polyhedron, strength, quadrature.subdivision_levels);
    case HarmonicRuleKind::monte_carlo:
      return polyhedron_monte_carlo_rule(polyhedron, quadrature.monte_carlo_points, seed);
    case HarmonicRuleKind::cone: break;
  }
  // A cell star-shaped about no point (a sliced tube's cut cells, their inner wall concave)
  // gets positive weights on points inside it. As few as C(strength + 3, 3) of them leave a
  // cell of hundreds of nodes a stiffness of rank 3 × #points and a mass of rank #points:
  // hourglass modes on the nodes no other cell holds, and a matrix CHOLMOD refuses (the
  // sliced tube failed at step 1). Twice #nodes points give both full rank with room.
  const auto nodes = static_cast<int>(polyhedron.vertices.rows());
  return simplified_polyhedron_rule(polyhedron, strength, quadrature.simplifier, 2 * nodes);
}

}  // namespace altfem::harmonic
