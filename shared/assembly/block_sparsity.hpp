#pragma once
#include <Eigen/SparseCore>
#include <span>
#include <vector>

#include "shared/assembly/basis_groups.hpp"
#include "shared/assembly/tabulated_elements.hpp"

namespace altfem {

using SparseMatrix = Eigen::SparseMatrix<double>;  // column-major; symmetric matrices stored full

/// The sparsity of a 3-component discretization's matrices (stiffness, mass and any
/// matrix the integrators build: one pattern for all, so M/h² + K is a sum of value
/// arrays), computed once, with the place of every element's basis-pair block in it so
/// that values are refilled in place at every assembly.
///
/// Basis functions g and h couple when an element holds both, or when a group of
/// `extra` couplings (a face's two neighbours, say) holds both; DOF 3g+k's column then
/// holds rows 3h, 3h+1, 3h+2 consecutively. The three columns of one basis function
/// have the same rows, so one offset per pair serves all nine entries of the block.
///
/// One rank's share of a run over several processes (docs/scaling.md) passes `included`
/// (#elements + #extra groups, nonzero for the groups it assembles): the pattern then holds
/// only their blocks, plus every basis function's diagonal block (what Dirichlet
/// elimination and a solver's rows need of every function), and a left-out group has no
/// offsets.
class BlockSparsity {
public:
  explicit BlockSparsity(const TabulatedElements& elements, const BasisGroups& extra = {},
                         std::span<const char> included = {});

  /// A compressed #dofs × #dofs matrix with this pattern and zero values.
  const SparseMatrix& pattern() const { return pattern_; }
  /// For element e and its local basis functions a (row) and b (column): the offset
  /// of row 3·g_a inside column 3·g_b + k, for k = 0, 1, 2 (#basis × #basis, column-major
  /// by b). Value index = outerIndexPtr()[3 g_b + k] + offset + i.
  const int* pair_offsets(int element) const { return offsets_.data() + group_offsets_[element]; }
  /// The same for group g of the extra couplings (#group × #group). A group left out of
  /// `included` has none.
  const int* extra_pair_offsets(int group) const { return offsets_.data() + group_offsets_[element_count_ + group]; }

private:
  SparseMatrix pattern_;
  int element_count_ = 0;
  std::vector<long long> group_offsets_;  // elements first, then the extra groups
  std::vector<int> offsets_;
};

}  // namespace altfem
