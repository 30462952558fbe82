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

// The defaults, measured (docs/scene-schema.md, "harmonic"): on the bending prism sliced at
// 8 (build/bin/verify_harmonic_quadrature) the full cone rule of strength 2 has 155 points
// per MFS cell and H1 error 9.16e-4; simplified to 10 points (any simplifier) H1 grows to
// 1.5–2.0e-3, because 10 points give a cell of 14–30 nodes a rank-deficient stiffness (on
// the sliced hollow ball, neo-Hookean, Newton then meets an indefinite tangent and fails);
// subdivision (422 / 3303 points) and Monte Carlo (797 with 1000 samples) give errors
// within 1% of the cone rule's for 3–20× its points. So: the cone rule, not simplified.
struct HarmonicQuadrature {
  HarmonicRuleKind kind = HarmonicRuleKind::cone;
  /// `cone` only: the simplifier of simplified_polyhedron_rule, nullopt for the full cone rule.
  std::optional<SimplificationMethod> simplifier = std::nullopt;
  int subdivision_levels = 3;     ///< `subdivision`: 2^levels boxes per axis
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
