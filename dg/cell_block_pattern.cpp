#include "dg/cell_block_pattern.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "shared/solve/huge_page_allocation.hpp"

namespace altfem::dg {

CellBlockPattern::CellBlockPattern(std::vector<int> offsets, const std::vector<std::array<int, 2>>& couplings,
                                   std::vector<char> diagonal_only)
    : offsets_(std::move(offsets)), diagonal_only_(std::move(diagonal_only)) {
  const int cells = static_cast<int>(offsets_.size()) - 1;
  const auto blockless = [&](int cell) { return !diagonal_only_.empty() && diagonal_only_[cell]; };
  std::vector<std::vector<int>> adjacent(cells);
  for (int cell = 0; cell < cells; ++cell)
    if (!blockless(cell)) adjacent[cell].push_back(cell);
  for (const auto& [first, second] : couplings) {
    if (blockless(first) || blockless(second))
      throw std::logic_error("CellBlockPattern: a coupling of cells " + std::to_string(first) + " and " +
                             std::to_string(second) + ", one of them without blocks");
    adjacent[first].push_back(second);
    adjacent[second].push_back(first);
  }
  first_neighbour_.reserve(cells + 1);
  first_neighbour_.push_back(0);
  for (std::vector<int>& list : adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    int row = 0;
    for (int neighbour : list) {
      neighbours_.push_back(neighbour);
      row_starts_.push_back(row);
      row += 3 * (offsets_[neighbour + 1] - offsets_[neighbour]);
    }
    first_neighbour_.push_back(static_cast<int>(neighbours_.size()));
  }
}

void CellBlockPattern::make_zero_matrix(Eigen::SparseMatrix<double>& matrix) const {
  const int cells = static_cast<int>(offsets_.size()) - 1;
  const Eigen::Index dofs = 3 * static_cast<Eigen::Index>(offsets_.back());
  // Rows per column of each cell: the DOFs of its neighbours.
  long long nonzeros = 0;
  for (int cell = 0; cell < cells; ++cell) {
    long long rows = first_neighbour_[cell] == first_neighbour_[cell + 1] ? 1 : 0;  // diagonal only
    for (int k = first_neighbour_[cell]; k < first_neighbour_[cell + 1]; ++k)
      rows += 3 * (offsets_[neighbours_[k] + 1] - offsets_[neighbours_[k]]);
    nonzeros += rows * 3 * (offsets_[cell + 1] - offsets_[cell]);
  }
  if (nonzeros > std::numeric_limits<int>::max())
    throw std::length_error("CellBlockPattern: " + std::to_string(nonzeros) + " nonzeros exceed the index type");
  matrix.resize(dofs, dofs);
  matrix.data().clear();
  matrix.data().squeeze();
  matrix.resizeNonZeros(static_cast<Eigen::Index>(nonzeros));
  // Tens of MB written once: their first touch faults per huge page, not per 4 KiB page.
  advise_huge_pages(matrix.valuePtr(), sizeof(double) * static_cast<size_t>(nonzeros));
  advise_huge_pages(matrix.innerIndexPtr(), sizeof(int) * static_cast<size_t>(nonzeros));
  int* outer = matrix.outerIndexPtr();
  int* inner = matrix.innerIndexPtr();
  std::fill_n(matrix.valuePtr(), nonzeros, 0.0);
  int position = 0;
  for (int cell = 0; cell < cells; ++cell)
    for (int column = 3 * offsets_[cell]; column < 3 * offsets_[cell + 1]; ++column) {
      outer[column] = position;
      if (first_neighbour_[cell] == first_neighbour_[cell + 1]) inner[position++] = column;  // diagonal only
      for (int k = first_neighbour_[cell]; k < first_neighbour_[cell + 1]; ++k)
        for (int row = 3 * offsets_[neighbours_[k]]; row < 3 * offsets_[neighbours_[k] + 1]; ++row)
          inner[position++] = row;
    }
  outer[dofs] = position;
}

void CellBlockPattern::add_block(Eigen::SparseMatrix<double>& matrix, int row_cell, int column_cell,
                                 const Eigen::Ref<const Eigen::MatrixXd>& block) const {
  const auto first = neighbours_.begin() + first_neighbour_[column_cell];
  const auto last = neighbours_.begin() + first_neighbour_[column_cell + 1];
  const auto found = std::lower_bound(first, last, row_cell);
  if (found == last || *found != row_cell)
    throw std::logic_error("CellBlockPattern: cells " + std::to_string(row_cell) + " and " +
                           std::to_string(column_cell) + " are not coupled");
  if (block.rows() != 3 * (offsets_[row_cell + 1] - offsets_[row_cell]) ||
      block.cols() != 3 * (offsets_[column_cell + 1] - offsets_[column_cell]))
    throw std::logic_error("CellBlockPattern: a " + std::to_string(block.rows()) + " x " +
                           std::to_string(block.cols()) + " block for cells " + std::to_string(row_cell) + ", " +
                           std::to_string(column_cell));
  const int row_start = row_starts_[found - neighbours_.begin()];
  const int first_column = 3 * offsets_[column_cell];
  for (Eigen::Index j = 0; j < block.cols(); ++j) {
    double* column = matrix.valuePtr() + matrix.outerIndexPtr()[first_column + j] + row_start;
    Eigen::Map<Eigen::VectorXd>(column, block.rows()) += block.col(j);
  }
}

}  // namespace altfem::dg
