#pragma once
// Strongly imposed Dirichlet conditions as a Discretization states them: the
// constrained DOFs and their prescribed values over time.
#include <Eigen/Core>
#include <functional>
#include <vector>

namespace altfem {

struct DirichletDofs {
  std::vector<int> dofs;  ///< sorted, unique
  /// The prescribed displacements at a time, in `dofs` order (#dofs entries).
  std::function<Eigen::VectorXd(double time)> prescribed;
};

}  // namespace altfem
