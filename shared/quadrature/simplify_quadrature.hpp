#pragma once
// Quadrature simplification (Longva et al. 2020, §4.4): from a rule with positive
// weights, pick at most M = C(degree+3, 3) of its points and new positive weights that
// integrate every polynomial of total degree <= degree as the original rule does.
// Points stay where they were, so they stay inside whatever domain the original
// covered. Generic: nothing here knows about cells or embeddings.
#include <array>
#include <optional>
#include <string_view>

#include "shared/quadrature/quadrature_rule.hpp"

namespace altfem {

enum class SimplificationMethod {
  linear_program,             ///< Clp's simplex on the transformed LP, eq. (10)
  nonnegative_least_squares,  ///< Lawson–Hanson on the same system (no LP solver)
  caratheodory                ///< Carathéodory–Steinitz recombination (caratheodory_recombination.hpp)
};

/// "lp", "nnls" or "caratheodory".
std::string_view simplification_method_name(SimplificationMethod method);

/// The values of a scene's `simplifier` key (fcm, dg, harmonic): a method, or no simplification.
inline constexpr std::array<std::string_view, 4> simplifier_names{"caratheodory", "nnls", "lp", "none"};
/// The method a simplifier_names entry names, nullopt for "none". Throws
/// std::invalid_argument for any other name (the scene schema has checked the choice).
std::optional<SimplificationMethod> simplifier_from_name(std::string_view name);

struct SimplificationOptions {
  int degree = 2;
  /// Measured faster at equal accuracy (docs/quadrature.md): see the default there.
  SimplificationMethod method = SimplificationMethod::caratheodory;
  /// Largest accepted moment residual (see SimplificationResult::residual).
  double tolerance = 1e-12;
};

struct SimplificationResult {
  QuadratureRule rule;      ///< the simplified rule, or the original one if not simplified
  bool simplified = false;  ///< false when the input had <= M points, or on failure
  bool failed = false;      ///< the solver failed or its residual exceeded the tolerance: original kept
  /// max_i |Σ_j p_i(x_j) (w_j − w⁰_j)| / Σ_j |w⁰_j| over the scaled Chebyshev basis p_i
  /// (|p_i| <= 1 on the points' box): the relative moment error of the simplified
  /// candidate, reported even when it was rejected (then `rule` is the original);
  /// 0 when nothing was attempted.
  double residual = 0.0;
};

/// rule.points: #points × 3 (any coordinates: the basis is fitted to their box);
/// weights must be >= 0. The original rule is returned unchanged (simplified = false)
/// when it has at most M points; never throws on a solver failure (failed = true).
/// Throws std::invalid_argument on a negative weight, degree < 0 or non-3D points.
SimplificationResult simplify_quadrature(const QuadratureRule& rule, const SimplificationOptions& options);

}  // namespace altfem
