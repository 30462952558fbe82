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
  return simplified_polyhedron_rule(polyhedron, strength, quadrature.simplifier);
}

}  // namespace altfem::harmonic
