#include "shared/solve/galerkin_product.hpp"

#include <omp.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "shared/solve/huge_page_allocation.hpp"
#include "shared/solve/identical_pattern_classes.hpp"
#include "shared/solve/symmetric_from_upper.hpp"

namespace altfem {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// The arrays of a compressed column-major matrix: column c holds inner[outer[c] .. outer[c + 1]).
struct CompressedColumns {
  const int* outer;
  const int* inner;
  const double* value;

  int length(int column) const { return outer[column + 1] - outer[column]; }
};

/// Resizes a vector that is empty so far to `size` elements, asking for huge pages behind it
/// first: the large buffers of one product (A's ordered copy and the upper triangle, megabytes
/// each, like the result: symmetric_from_upper) are fresh memory on every call, and faulting
/// them in 4 KiB at a time cost a third of the product's time in bench_galerkin_product.
template <class Value>
void resize_on_huge_pages(std::vector<Value>& buffer, size_t size) {
  buffer.reserve(size);
  advise_huge_pages(buffer.data(), size * sizeof(Value));
  buffer.resize(size);
}

CompressedColumns columns_of(const SparseMatrix& matrix) {
  return {matrix.outerIndexPtr(), matrix.innerIndexPtr(), matrix.valuePtr()};
}

/// `matrix` itself when compressed, else a compressed copy in `storage`.
const SparseMatrix& compressed(const SparseMatrix& matrix, SparseMatrix& storage) {
  if (matrix.isCompressed()) return matrix;
  storage = matrix;
  storage.makeCompressed();
  return storage;
}

/// `matrix` compressed with sorted row indices in every column: itself when it already is,
/// else a sorted copy in `storage` (a transposed copy sorts).
const SparseMatrix& compressed_sorted(const SparseMatrix& matrix, SparseMatrix& storage) {
  bool sorted = matrix.isCompressed();
  for (Eigen::Index column = 0; sorted && column < matrix.outerSize(); ++column)
    for (int at = matrix.outerIndexPtr()[column] + 1; sorted && at < matrix.outerIndexPtr()[column + 1]; ++at)
      sorted = matrix.innerIndexPtr()[at - 1] < matrix.innerIndexPtr()[at];
  if (sorted) return matrix;
  const Eigen::SparseMatrix<double, Eigen::RowMajor> transposed = matrix;
  storage = transposed;
  return storage;
}

/// A restricted to the rows P uses, each column's pattern reordered by the first (smallest)
/// coarse column of its rows in P: the rows of y = A P e_j that the upper triangle's column j
/// reads (those whose P row reaches a column ≤ j) are then a prefix of every column, whose
/// length a binary search in the class's `first_coarse` finds. All columns of a class share
/// one order, so runs of them still add up densely.
struct OrderedMatrix {
  std::vector<int> outer, inner;  // n + 1 and the kept entries: A's numbering, unused columns empty
  std::vector<double> value;
  std::vector<int> class_outer, first_coarse;  // per class: its rows' first coarse columns, increasing
};

OrderedMatrix ordered_by_first_coarse(const CompressedColumns& matrix, const CompressedColumns& restriction,
                                      const std::vector<int>& classes, int class_count, const std::vector<char>& used) {
  const int size = static_cast<int>(classes.size());
  std::vector<int> representative(static_cast<size_t>(class_count), -1);
  for (int column = size - 1; column >= 0; --column)
    if (classes[column] >= 0) representative[classes[column]] = column;
  OrderedMatrix ordered;
  ordered.class_outer.assign(static_cast<size_t>(class_count) + 1, 0);
  for (int c = 0; c < class_count; ++c) {
    const int column = representative[c];
    int length = 0;
    for (int at = matrix.outer[column]; at < matrix.outer[column + 1]; ++at) length += used[matrix.inner[at]];
    ordered.class_outer[c + 1] = ordered.class_outer[c] + length;
  }
  // Per class: positions in its (unrestricted) pattern of the used rows, by first coarse column.
  std::vector<int> positions(static_cast<size_t>(ordered.class_outer[class_count]));
  ordered.first_coarse.resize(positions.size());
  for (int c = 0; c < class_count; ++c) {
    const int column = representative[c];
    int* order = positions.data() + ordered.class_outer[c];
    int count = 0;
    for (int at = matrix.outer[column]; at < matrix.outer[column + 1]; ++at)
      if (used[matrix.inner[at]]) order[count++] = at - matrix.outer[column];
    const auto first_coarse_of = [&](int position) {
      const int row = matrix.inner[matrix.outer[column] + position];
      return restriction.inner[restriction.outer[row]];
    };
    std::stable_sort(order, order + count, [&](int a, int b) { return first_coarse_of(a) < first_coarse_of(b); });
    for (int q = 0; q < count; ++q) ordered.first_coarse[ordered.class_outer[c] + q] = first_coarse_of(order[q]);
  }
  ordered.outer.assign(static_cast<size_t>(size) + 1, 0);
  for (int column = 0; column < size; ++column) {
    const int c = classes[column];
    ordered.outer[column + 1] =
        ordered.outer[column] + (c >= 0 ? ordered.class_outer[c + 1] - ordered.class_outer[c] : 0);
  }
  resize_on_huge_pages(ordered.inner, static_cast<size_t>(ordered.outer[size]));
  resize_on_huge_pages(ordered.value, ordered.inner.size());
  for (int column = 0; column < size; ++column) {
    const int c = classes[column];
    if (c < 0) continue;
    const int* order = positions.data() + ordered.class_outer[c];
    const int from = matrix.outer[column], to = ordered.outer[column];
    for (int q = 0; q < ordered.outer[column + 1] - to; ++q) {
      ordered.inner[to + q] = matrix.inner[from + order[q]];
      ordered.value[to + q] = matrix.value[from + order[q]];
    }
  }
  return ordered;
}

/// What the column loop reads: A (ordered), P, Pᵀ, and the groups of identical patterns.
struct ProductInputs {
  CompressedColumns matrix, prolongation, restriction;  // A ordered (OrderedMatrix), P, Pᵀ
  const int* class_outer;                               // A's classes: first coarse columns, OrderedMatrix
  const int* first_coarse;
  int fine_size, coarse_size;
  std::vector<int> matrix_class;              // per column of A: its pattern class (-1: unused)
  std::vector<int> restriction_class;         // per fine row: the class of its pattern in P (-1: empty row)
  std::vector<int> member_outer, members;     // the fine rows of each restriction class
  int longest_column = 0, largest_class = 0;  // scratch sizes
};

/// values[index] += addend in column `column` of a dense accumulator whose entries are valid
/// only where marker == column (else zero), listing each valid entry once in listed[0 .. count).
/// Raw pointers and the caller's count: members of a struct would be reloaded after every
/// store through marker and listed (both int), 5% of the product.
inline void accumulate(int index, double addend, int column, double* values, int* marker, int* listed, int& count) {
  if (marker[index] != column) {
    marker[index] = column;
    values[index] = 0;
    listed[count++] = index;
  }
  values[index] += addend;
}

/// Columns [begin, end) of the upper triangle. Column j of Pᵀ A P is Pᵀ (A (P e_j)): first
/// y = A P e_j into a dense fine vector (accumulate: a marker per row records whether it is set
/// in this column, a list which rows are), then the rows i ≤ j of Pᵀ y into a dense coarse one;
/// y is formed only in the rows whose P row reaches a column ≤ j (OrderedMatrix).
/// Runs of P's column entries whose A columns share a pattern are summed densely first and
/// scattered once; Pᵀ y is taken per class of fine rows with one pattern in P likewise.
void upper_columns(const ProductInputs& inputs, UpperColumns& upper) {
  const CompressedColumns& a = inputs.matrix;
  const CompressedColumns& p = inputs.prolongation;
  const CompressedColumns& r = inputs.restriction;
  std::vector<double> fine(static_cast<size_t>(inputs.fine_size)), coarse(static_cast<size_t>(inputs.coarse_size));
  std::vector<int> fine_marker(static_cast<size_t>(inputs.fine_size), -1), fine_rows(fine.size());
  std::vector<int> coarse_marker(coarse.size(), -1), coarse_rows(coarse.size());
  std::vector<int> class_marker(inputs.member_outer.size() - 1, -1);
  std::vector<double> dense(static_cast<size_t>(inputs.longest_column)),
      gathered(static_cast<size_t>(inputs.largest_class));
  // Filled here and moved into `upper` at the end: the ranges of the threads lie side by side,
  // and growing their vectors in place would share cache lines between the threads.
  std::vector<int> outer(static_cast<size_t>(upper.end - upper.begin) + 1, 0), inner;
  std::vector<double> value;
  // A first guess of the size: DG's vertex coarse space needs 3.8 upper entries per entry of P.
  resize_on_huge_pages(inner, 4 * static_cast<size_t>(p.outer[upper.end] - p.outer[upper.begin]));
  resize_on_huge_pages(value, inner.size());
  int count = 0;

  for (int j = upper.begin; j < upper.end; ++j) {
    int fine_count = 0;
    for (int run = p.outer[j]; run < p.outer[j + 1];) {
      const int first = p.inner[run], pattern_class = inputs.matrix_class[first];
      int run_end = run + 1;
      while (run_end < p.outer[j + 1] && inputs.matrix_class[p.inner[run_end]] == pattern_class) ++run_end;
      const int* first_coarse = inputs.first_coarse + inputs.class_outer[pattern_class];
      const int length =
          static_cast<int>(std::upper_bound(first_coarse, first_coarse + a.length(first), j) - first_coarse);
      const int* rows = a.inner + a.outer[first];
      const double* values = a.value + a.outer[first];
      for (int t = 0; t < length; ++t) dense[t] = values[t] * p.value[run];
      for (int entry = run + 1; entry < run_end; ++entry) {
        values = a.value + a.outer[p.inner[entry]];
        const double weight = p.value[entry];
        for (int t = 0; t < length; ++t) dense[t] += values[t] * weight;
      }
      for (int t = 0; t < length; ++t)
        accumulate(rows[t], dense[t], j, fine.data(), fine_marker.data(), fine_rows.data(), fine_count);
      run = run_end;
    }

    int coarse_count = 0;
    for (int t = 0; t < fine_count; ++t) {
      const int pattern_class = inputs.restriction_class[fine_rows[t]];
      if (class_marker[pattern_class] == j) continue;
      class_marker[pattern_class] = j;
      const int* members = inputs.members.data() + inputs.member_outer[pattern_class];
      const int member_count = inputs.member_outer[pattern_class + 1] - inputs.member_outer[pattern_class];
      for (int g = 0; g < member_count; ++g) gathered[g] = fine_marker[members[g]] == j ? fine[members[g]] : 0.0;
      const int* rows = r.inner + r.outer[members[0]];
      int length = 0;  // the rows ≤ j (Pᵀ's columns are sorted)
      while (length < r.length(members[0]) && rows[length] <= j) ++length;
      const double* values = r.value + r.outer[members[0]];
      for (int s = 0; s < length; ++s) dense[s] = values[s] * gathered[0];
      for (int g = 1; g < member_count; ++g) {
        values = r.value + r.outer[members[g]];
        for (int s = 0; s < length; ++s) dense[s] += values[s] * gathered[g];
      }
      for (int s = 0; s < length; ++s)
        accumulate(rows[s], dense[s], j, coarse.data(), coarse_marker.data(), coarse_rows.data(), coarse_count);
    }
    if (count + coarse_count > static_cast<int>(inner.size())) {  // grows geometrically: O(log nnz) times
      const size_t grown = std::max<size_t>(2 * inner.size(), static_cast<size_t>(count + coarse_count));
      std::vector<int> more_inner;
      std::vector<double> more_value;
      resize_on_huge_pages(more_inner, grown);
      resize_on_huge_pages(more_value, grown);
      std::copy_n(inner.begin(), count, more_inner.begin());
      std::copy_n(value.begin(), count, more_value.begin());
      inner.swap(more_inner);
      value.swap(more_value);
    }
    for (int t = 0; t < coarse_count; ++t, ++count) {
      inner[count] = coarse_rows[t];
      value[count] = coarse[coarse_rows[t]];
    }
    outer[j - upper.begin + 1] = count;
  }
  upper.outer = std::move(outer);
  upper.inner = std::move(inner);
  upper.value = std::move(value);
}

}  // namespace

SparseMatrix galerkin_product(const SparseMatrix& matrix, const SparseMatrix& prolongation,
                              const SparseMatrix& restriction) {
  const Eigen::Index fine_size = prolongation.rows(), coarse_size = prolongation.cols();
  if (matrix.rows() != fine_size || matrix.cols() != fine_size || restriction.rows() != coarse_size ||
      restriction.cols() != fine_size)
    throw std::invalid_argument("galerkin_product: A is " + std::to_string(matrix.rows()) + " × " +
                                std::to_string(matrix.cols()) + ", P " + std::to_string(fine_size) + " × " +
                                std::to_string(coarse_size) + ", Pᵀ " + std::to_string(restriction.rows()) + " × " +
                                std::to_string(restriction.cols()) + ": expected n × n, n × m and m × n");
  SparseMatrix matrix_storage, prolongation_storage, restriction_storage;
  ProductInputs inputs;
  inputs.fine_size = static_cast<int>(fine_size);
  inputs.coarse_size = static_cast<int>(coarse_size);
  // Only Pᵀ's columns must be sorted (the rows ≤ j are a prefix); A's and P's order is free:
  // grouping compares patterns as sequences.
  inputs.prolongation = columns_of(compressed(prolongation, prolongation_storage));
  inputs.restriction = columns_of(compressed_sorted(restriction, restriction_storage));
  const CompressedColumns& r = inputs.restriction;

  // The fine rows P uses: A is restricted to them (a DG vertex coarse space at k = 2 uses 12k
  // of 30k rows, so A P e_j then reads 2.5× fewer entries).
  std::vector<char> used(static_cast<size_t>(fine_size));
  int used_count = 0;
  for (int row = 0; row < inputs.fine_size; ++row) {
    used[row] = r.length(row) > 0;
    used_count += used[row];
  }
  const CompressedColumns unordered = columns_of(compressed(matrix, matrix_storage));

  int matrix_classes = 0, restriction_classes = 0;
  inputs.matrix_class = identical_pattern_classes(unordered.outer, unordered.inner, used, matrix_classes);
  const OrderedMatrix ordered = ordered_by_first_coarse(unordered, r, inputs.matrix_class, matrix_classes, used);
  inputs.matrix = {ordered.outer.data(), ordered.inner.data(), ordered.value.data()};
  inputs.class_outer = ordered.class_outer.data();
  inputs.first_coarse = ordered.first_coarse.data();
  inputs.restriction_class = identical_pattern_classes(r.outer, r.inner, used, restriction_classes);
  inputs.member_outer.assign(static_cast<size_t>(restriction_classes) + 1, 0);
  for (int row = 0; row < inputs.fine_size; ++row)
    if (used[row]) ++inputs.member_outer[inputs.restriction_class[row] + 1];
  for (int c = 0; c < restriction_classes; ++c) {
    inputs.largest_class = std::max(inputs.largest_class, inputs.member_outer[c + 1]);
    inputs.member_outer[c + 1] += inputs.member_outer[c];
  }
  inputs.members.resize(static_cast<size_t>(used_count));
  std::vector<int> fill(inputs.member_outer.begin(), inputs.member_outer.end() - 1);
  for (int row = 0; row < inputs.fine_size; ++row)
    if (used[row]) inputs.members[fill[inputs.restriction_class[row]]++] = row;
  for (int column = 0; column < inputs.fine_size; ++column)
    inputs.longest_column = std::max({inputs.longest_column, inputs.matrix.length(column), r.length(column)});

  // Contiguous ranges of columns, one per thread, each with its own scratch.
  std::vector<UpperColumns> ranges(
      static_cast<size_t>(std::max(1, std::min(omp_get_max_threads(), inputs.coarse_size))));
  const int range_count = static_cast<int>(ranges.size());
#pragma omp parallel for schedule(static, 1) num_threads(range_count)
  for (int range = 0; range < range_count; ++range) {
    ranges[range].begin = static_cast<int>(static_cast<long>(inputs.coarse_size) * range / range_count);
    ranges[range].end = static_cast<int>(static_cast<long>(inputs.coarse_size) * (range + 1) / range_count);
    upper_columns(inputs, ranges[range]);
  }
  return symmetric_from_upper(ranges, inputs.coarse_size);
}

}  // namespace altfem
