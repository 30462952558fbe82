#include "shared/solve/explicit_mass.hpp"

#include <stdexcept>
#include <string>

namespace altfem {

DiagonalMass::DiagonalMass(Eigen::VectorXd diagonal) : diagonal_(std::move(diagonal)) {
  if (!(diagonal_.array() > 0).all())
    throw std::invalid_argument("DiagonalMass: every diagonal entry must be positive");
}

BlockDiagonalMass::BlockDiagonalMass(const Eigen::SparseMatrix<double>& mass,
                                     const std::vector<std::vector<int>>& groups)
    : groups_(groups) {
  const Eigen::Index dofs = mass.rows();
  std::vector<int> group_of(static_cast<size_t>(dofs), -1);
  for (size_t g = 0; g < groups_.size(); ++g)
    for (int dof : groups_[g]) {
      if (dof < 0 || dof >= dofs || group_of[dof] >= 0)
        throw std::invalid_argument("BlockDiagonalMass: DOF " + std::to_string(dof) +
                                    " is out of range or in two groups");
      group_of[dof] = static_cast<int>(g);
    }
  for (Eigen::Index dof = 0; dof < dofs; ++dof)
    if (group_of[dof] < 0)
      throw std::invalid_argument("BlockDiagonalMass: DOF " + std::to_string(dof) + " is in no group");

  std::vector<int> local(static_cast<size_t>(dofs));
  for (const auto& group : groups_)
    for (size_t i = 0; i < group.size(); ++i) local[group[i]] = static_cast<int>(i);
  blocks_.reserve(groups_.size());
  for (const auto& group : groups_) blocks_.emplace_back(Eigen::MatrixXd::Zero(group.size(), group.size()));
  for (Eigen::Index column = 0; column < mass.outerSize(); ++column)
    for (Eigen::SparseMatrix<double>::InnerIterator entry(mass, column); entry; ++entry) {
      const int g = group_of[entry.row()];
      if (g != group_of[column]) {
        if (entry.value() != 0.0)
          throw std::invalid_argument("BlockDiagonalMass: the mass couples DOFs " + std::to_string(entry.row()) +
                                      " and " + std::to_string(column) + " of different groups");
        continue;
      }
      blocks_[g](local[entry.row()], local[column]) = entry.value();
    }
  factors_.reserve(groups_.size());
  for (size_t g = 0; g < groups_.size(); ++g) {
    factors_.emplace_back(blocks_[g]);
    if (factors_.back().info() != Eigen::Success)
      throw std::invalid_argument("BlockDiagonalMass: block " + std::to_string(g) + " is not positive definite");
  }
}

template <typename BlockOperation>
Eigen::VectorXd BlockDiagonalMass::per_block(const Eigen::VectorXd& v, BlockOperation&& operation) const {
  Eigen::VectorXd result(v.size());
  for (size_t g = 0; g < groups_.size(); ++g) {
    const auto& group = groups_[g];
    Eigen::VectorXd local(static_cast<Eigen::Index>(group.size()));
    for (size_t i = 0; i < group.size(); ++i) local[static_cast<Eigen::Index>(i)] = v[group[i]];
    local = operation(g, local);
    for (size_t i = 0; i < group.size(); ++i) result[group[i]] = local[static_cast<Eigen::Index>(i)];
  }
  return result;
}

Eigen::VectorXd BlockDiagonalMass::multiply(const Eigen::VectorXd& v) const {
  return per_block(v, [&](size_t g, const Eigen::VectorXd& local) -> Eigen::VectorXd { return blocks_[g] * local; });
}

Eigen::VectorXd BlockDiagonalMass::solve(const Eigen::VectorXd& f) const {
  return per_block(f,
                   [&](size_t g, const Eigen::VectorXd& local) -> Eigen::VectorXd { return factors_[g].solve(local); });
}

}  // namespace altfem
