#pragma once
// Columns of a sparse pattern that are identical, found in one pass: galerkin_product takes
// such columns as a group (DG's cell blocks: every function of a cell couples to the same
// neighbours), adding their values densely and scattering once.
#include <vector>

namespace altfem {

/// A class id per column of the compressed column-major pattern (column c holds the rows
/// inner[outer[c] .. outer[c + 1]), kept.size() columns) such that two kept columns share it
/// exactly when their rows are the same sequence; -1 for columns not kept; `class_count` ids
/// in all, numbered in the order of their first columns. Patterns are bucketed by a hash of
/// their rows and verified entry by entry against the bucket's first column; a column whose
/// hash collides with a different pattern gets a class of its own, which costs grouping,
/// never correctness.
std::vector<int> identical_pattern_classes(const int* outer, const int* inner, const std::vector<char>& kept,
                                           int& class_count);

}  // namespace altfem
