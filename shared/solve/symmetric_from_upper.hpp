#pragma once
// A symmetric sparse matrix from the columns of its upper triangle, given with their rows in
// any order: both triangles with sorted rows, and no sort. galerkin_product forms only the
// upper triangle of Pᵀ A P, column by column, in ranges (one per thread).
#include <Eigen/SparseCore>
#include <vector>

namespace altfem {

/// Columns [begin, end) of the upper triangle of a symmetric matrix (row ≤ column), rows in
/// any order: column j holds inner[outer[j − begin] .. outer[j − begin + 1]) and `value`
/// likewise (inner and value may be longer than outer.back()).
struct UpperColumns {
  int begin = 0, end = 0;
  std::vector<int> outer, inner;
  std::vector<double> value;
};

/// The size × size symmetric matrix whose upper triangle the ranges hold (in order, together
/// covering 0 .. size): compressed, both triangles, sorted rows. The upper entries U(i, j) are
/// first written transposed, column by column in increasing j, into the lower parts (rows ≥ i)
/// of their columns i, which leaves those sorted; the lower parts are then read in increasing
/// i and written transposed into the upper parts (rows < j), sorted likewise. The result's
/// arrays are asked for huge pages before they are touched (huge_page_allocation.hpp).
Eigen::SparseMatrix<double> symmetric_from_upper(const std::vector<UpperColumns>& ranges, int size);

}  // namespace altfem
