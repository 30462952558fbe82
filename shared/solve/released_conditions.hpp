#pragma once
// A discretization with some of the scene's Dirichlet conditions released (a `release`
// event, docs/scene-schema.md "events"): the DOFs that only released conditions held
// become free. Nothing is re-integrated: the energy, the mass and the pattern are the
// inner discretization's; only the constrained set shrinks.
#include <stdexcept>
#include <vector>

#include "shared/solve/forwarding_discretization.hpp"

namespace altfem {

class ReleasedConditions final : public ForwardingDiscretization {
public:
  /// Throws std::invalid_argument saying why when a condition in `released` cannot be
  /// released: the inner discretization does not record its DOFs' conditions, or a DOF
  /// still held by another condition takes its value from a released one.
  ReleasedConditions(const Discretization& inner, ConditionSet released);

  const std::vector<int>& constrained_dofs() const override { return dofs_; }
  Eigen::VectorXd prescribed_displacement(double time) const override;
  const std::vector<ConstraintHolders>& constraint_holders() const override { return holders_; }

  /// The DOFs the release freed.
  int freed_dofs() const { return static_cast<int>(inner().constrained_dofs().size() - dofs_.size()); }

private:
  std::vector<int> dofs_;  // the DOFs still constrained
  std::vector<int> kept_;  // their entries in the inner constrained_dofs() order
  std::vector<ConstraintHolders> holders_;
};

/// The DOFs of `discretization` that `condition` holds.
int dofs_held_by(const Discretization& discretization, int condition);

}  // namespace altfem
