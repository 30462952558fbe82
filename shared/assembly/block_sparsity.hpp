#pragma once
#include <Eigen/SparseCore>
#include <vector>

#include "shared/assembly/tabulated_elements.hpp"

namespace altfem {

using SparseMatrix = Eigen::SparseMatrix<double>;  // column-major; symmetric matrices stored full

/// The sparsity of a 3-component discretization's matrices (stiffness, mass: one
/// pattern for both, so M/h² + K is a sum of value arrays), computed once, with the
/// place of every element's basis-pair block in it so that values are refilled in
/// place at every assembly.
///
/// Basis functions g and h couple when an element holds both; DOF 3g+k's column then
/// holds rows 3h, 3h+1, 3h+2 consecutively. The three columns of one basis function
/// have the same rows, so one offset per pair serves all nine entries of the block.
class BlockSparsity {
public:
  explicit BlockSparsity(const TabulatedElements& elements);

  /// A compressed #dofs × #dofs matrix with this pattern and zero values.
  const SparseMatrix& pattern() const { return pattern_; }
  /// For element e and its local basis functions a (row) and b (column): the offset
  /// of row 3·g_a inside column 3·g_b + k, for k = 0, 1, 2 (#basis × #basis, column-major
  /// by b). Value index = outerIndexPtr()[3 g_b + k] + offset + i.
  const int* pair_offsets(int element) const { return offsets_.data() + element_offsets_[element]; }

private:
  SparseMatrix pattern_;
  std::vector<long long> element_offsets_;
  std::vector<int> offsets_;
};

}  // namespace altfem
