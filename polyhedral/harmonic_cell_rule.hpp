#pragma once
// The volume rule of an MFS cell (issue 19, "Consistency under quadrature"): the cone
// rule of the cell's tetrahedralisation, exact to its strength for polynomials and
// optionally simplified to at most C(strength+3, 3) points; or Martin et al. 2008 §6's
// own choices, bounding-box subdivision and Monte Carlo. harmonic_tabulation's
// consistency correction applies to every kind. Plain Tet4/Hex8 cells keep their
// reference rules whatever is chosen here.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "shared/geometry/polyhedron.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"
#include "shared/quadrature/simplify_quadrature.hpp"

namespace altfem::harmonic {

enum class HarmonicRuleKind { cone, subdivision, monte_carlo };
/// The values of /discretization/harmonic/rule, in HarmonicRuleKind's order.
inline constexpr std::array<std::string_view, 3> harmonic_rule_names{"cone", "subdivision", "monte_carlo"};

struct HarmonicQuadrature {
  HarmonicRuleKind kind = HarmonicRuleKind::cone;
  /// `cone` only: the simplifier of simplified_polyhedron_rule, nullopt for the full cone rule.
  std::optional<SimplificationMethod> simplifier = SimplificationMethod::caratheodory;
  int subdivision_levels = 3;   ///< `subdivision`: 2^levels boxes per axis
  int monte_carlo_points = 1000;  ///< `monte_carlo`: samples in the cell's bounding box
  /// harmonic_tabulation's consistency correction; false only to measure what it corrects.
  bool consistent = true;
};

/// The rule of `kind` of strength `strength` on `polyhedron` (the subdivision's boxes carry
/// tensor Gauss rules of that strength; Monte Carlo ignores it). `seed`: Monte Carlo's
/// (the cell's index, so cells draw different samples and runs repeat).
PolyhedronRule harmonic_cell_rule(const Polyhedron& polyhedron, int strength, const HarmonicQuadrature& quadrature,
                                  std::uint64_t seed);

}  // namespace altfem::harmonic
