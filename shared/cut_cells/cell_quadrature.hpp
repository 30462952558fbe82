#pragma once
// What the finite cell method needs to know of each background cell: how much of it
// lies inside the embedded geometry, and, for a cut cell, a rule that integrates over
// that part only, in the cell's reference coordinates (Longva et al. 2020 §4, eqs.
// (3)-(4): the FEM and the FCM differ only in the rules of cut cells).
#include <functional>
#include <optional>
#include <vector>

#include "shared/fem/lagrange_element_masses.hpp"
#include "shared/quadrature/quadrature_rule.hpp"

namespace altfem {

struct CellQuadrature {
  double volume_fraction = 0;          ///< vol(K ∩ Ω) / vol(K), in [0, 1]
  std::optional<QuadratureRule> rule;  ///< cut cells only: the rule of K ∩ Ω (reference coordinates)
  /// Mass rules of cut cells, where known: `rule` reduced (lagrange_element_masses' `reduced`).
  std::optional<ReferenceProducts> reduced;
};

/// What a set of rules is for: stiffness rules may be simplified to at most
/// C(m+3, 3) points (§4.4); mass rules are of a higher strength and never simplified (§6).
enum class RulePurpose { stiffness, mass };

/// The cells' quadrature for a polynomial strength, one entry per background cell.
using CellQuadratureSource = std::function<std::vector<CellQuadrature>(int strength, RulePurpose purpose)>;

}  // namespace altfem
