#pragma once
// Strongly imposed Dirichlet conditions as a Discretization states them: the
// constrained DOFs, their prescribed values over time, and which of the scene's
// conditions hold each (what a `release` event frees, released_conditions.hpp).
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

namespace altfem {

/// A set of the scene's Dirichlet conditions: bit c for /boundary_conditions/c (the
/// scene allows at most 64 conditions).
using ConditionSet = std::uint64_t;

inline ConditionSet condition_bit(int condition) { return ConditionSet{1} << condition; }

/// Which conditions hold one constrained DOF: every condition that selects it, and
/// those whose motions give its value (a nodal DOF: the last selecting one in the
/// scene's order; a DG coefficient: every condition on its cell's strong faces).
struct ConstraintHolders {
  ConditionSet conditions = 0;
  ConditionSet prescribing = 0;
};

struct DirichletDofs {
  std::vector<int> dofs;  ///< sorted, unique
  /// The prescribed displacements at a time, in `dofs` order (#dofs entries).
  std::function<Eigen::VectorXd(double time)> prescribed;
  /// Per DOF (`dofs` order) its holders; empty when not recorded (nothing can be released).
  std::vector<ConstraintHolders> holders;
};

}  // namespace altfem
