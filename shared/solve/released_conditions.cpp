#include "shared/solve/released_conditions.hpp"

#include <string>

namespace altfem {

ReleasedConditions::ReleasedConditions(const Discretization& inner, ConditionSet released)
    : ForwardingDiscretization(inner) {
  const std::vector<int>& dofs = inner.constrained_dofs();
  const std::vector<ConstraintHolders>& holders = inner.constraint_holders();
  if (holders.size() != dofs.size())
    throw std::invalid_argument("the discretization does not record which condition holds each constrained DOF");
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    const ConditionSet remaining = holders[i].conditions & ~released;
    if (remaining == 0) continue;  // only released conditions held it: free
    if (released & holders[i].prescribing)
      throw std::invalid_argument("DOF " + std::to_string(dofs[i]) +
                                  " is held by a released condition and by another one, and takes its value from the "
                                  "released one: release both, or make their regions disjoint");
    dofs_.push_back(dofs[i]);
    kept_.push_back(static_cast<int>(i));
    holders_.push_back({remaining, holders[i].prescribing});
  }
}

Eigen::VectorXd ReleasedConditions::prescribed_displacement(double time) const {
  const Eigen::VectorXd all = inner().prescribed_displacement(time);
  Eigen::VectorXd kept(static_cast<Eigen::Index>(kept_.size()));
  for (std::size_t i = 0; i < kept_.size(); ++i) kept[static_cast<Eigen::Index>(i)] = all[kept_[i]];
  return kept;
}

int dofs_held_by(const Discretization& discretization, int condition) {
  int count = 0;
  for (const ConstraintHolders& holders : discretization.constraint_holders())
    if (holders.conditions & condition_bit(condition)) ++count;
  return count;
}

}  // namespace altfem
