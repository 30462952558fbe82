#pragma once
// A coarser space inside a discretization's own, for multigrid's coarse level
// (Discretization::coarse_space; fem and fcm: their first-order space,
// shared/fem/first_order_space.hpp).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace altfem {

/// Coarse functions as functions of the fine basis (one scalar basis per displacement
/// component, as everywhere: function b carries DOFs 3b, 3b + 1, 3b + 2).
struct CoarseSpace {
  /// #basis functions × #coarse functions: column j holds coarse function j's values
  /// at the fine basis' nodes (the fine function that interpolates it).
  Eigen::SparseMatrix<double> prolongation;
  /// #coarse functions: the fine basis function at the same node (coarse function j
  /// is 1 there), so a nodal field's coarse values are its fine ones there. Where the
  /// fine basis is not nodal (dg's monomials): a fine function whose cell holds the
  /// coarse function's node, which places the coarse function on that function's rank.
  std::vector<int> fine_function;
  /// 3·#coarse functions × #modes, or empty: the near-null space at the coarse functions'
  /// nodes (the rigid-body motions there), for a space whose coarse values are not fine
  /// ones (dg's vertex space). Empty: the fine near-null space's rows at fine_function.
  Eigen::MatrixXd near_null_space;
  /// Whether GAMG coarsens this level without MIS-2 on the squared graph even for one
  /// solve per set-up (the method's measured choice, where the fewer iterations outweigh
  /// the dearer set-up of a level this small; else only where one set-up serves several).
  bool coarsen_gently = false;

  bool empty() const { return fine_function.empty(); }
};

}  // namespace altfem
