#pragma once
// The experiment of Longva et al. 2020, §4.6 (Fig. 4): a cuboid under a rigid motion
// with a non-zero rotation, embedded in a reference cell; its intersection rule and the
// simplified rule integrate every monomial of degree <= m in the cuboid's own frame
// (shifted so no integral vanishes), against the exact integrals.
#include <string>

#include "shared/element/element_type.hpp"
#include "shared/quadrature/simplify_quadrature.hpp"

namespace altfem::fcm {

/// The measurements of one rule: errors are relative, |err| / max(|exact|, ∫|f|).
struct RuleAccuracy {
  Eigen::Index points = 0;
  double max_relative_error = 0.0;
  double median_relative_error = 0.0;
  double min_weight = 0.0;
  bool inside = true;  ///< every point lies in the (closed) cuboid
};

struct MonomialExperiment {
  ElementType cell = ElementType::hex8;
  int order = 0;
  int basis_size = 0;  ///< M = C(m+3, 3)
  RuleAccuracy initial, simplified;
  double residual = 0.0;
  bool simplification_failed = false;
  double generation_seconds = 0.0, simplification_seconds = 0.0;
};

/// Runs the experiment on the reference cell of `cell` (geometry = identity map).
MonomialExperiment run_monomial_experiment(ElementType cell, int order, SimplificationMethod method);

}  // namespace altfem::fcm
