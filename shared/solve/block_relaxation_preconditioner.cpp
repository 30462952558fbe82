#include "shared/solve/block_relaxation_preconditioner.hpp"

#include <omp.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <atomic>
#include <string>

#include "shared/common/eigen_decompositions.hpp"
#include "shared/common/error.hpp"

namespace altfem {

namespace {

// Fewer blocks than this (Jacobi) are relaxed by one thread: a vertex block costs about a
// microsecond, less than waking a team of threads.
constexpr int minimum_parallel_blocks = 256;
// Gauss–Seidel with fewer blocks than this sweeps on one thread: a multicolour sweep wakes the
// team once per colour (~20 colours on a vertex level), each colour a few hundred blocks.
constexpr int minimum_parallel_sweep_blocks = 8192;

// Scratch for one block's values, on the stack up to 64 of them (a DG element block of
// degree 3 has 60), else on the heap.
class BlockScratch {
public:
  explicit BlockScratch(int size) {
    if (size > inline_size) heap_.resize(size);
  }
  double* data() { return heap_.size() > 0 ? heap_.data() : inline_; }

private:
  static constexpr int inline_size = 64;
  double inline_[inline_size];
  Eigen::VectorXd heap_;
};

// Greedy colouring of the block graph (blocks coupled by a nonzero of A are neighbours):
// each block, in order, takes the smallest colour none of its earlier neighbours has.
// Returns the colour of every block.
std::vector<int> colour_blocks(const Eigen::SparseMatrix<double>& matrix, const std::vector<int>& block_starts) {
  const int block_count = static_cast<int>(block_starts.size()) - 1;
  std::vector<int> block_of_dof(matrix.rows());
  for (int block = 0; block < block_count; ++block)
    std::fill(block_of_dof.begin() + block_starts[block], block_of_dof.begin() + block_starts[block + 1], block);
  std::vector<int> colour(block_count, -1), seen_by(block_count + 1, -1);
  for (int block = 0; block < block_count; ++block) {
    // Mark the colours of the block's coloured neighbours (any column of the block has
    // every row the block couples to, A being symmetric with a dense diagonal block).
    for (int column = block_starts[block]; column < block_starts[block + 1]; ++column)
      for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, column); entry; ++entry) {
        const int neighbour_colour = colour[block_of_dof[entry.row()]];
        if (neighbour_colour >= 0) seen_by[neighbour_colour] = block;
      }
    int chosen = 0;
    while (seen_by[chosen] == block) ++chosen;
    colour[block] = chosen;
  }
  return colour;
}

}  // namespace

BlockRelaxationPreconditioner::BlockRelaxationPreconditioner(std::vector<int> block_starts, BlockRelaxation relaxation)
    : block_starts_(std::move(block_starts)), relaxation_(relaxation) {
  if (block_starts_.empty() || block_starts_.front() != 0 ||
      !std::is_sorted(block_starts_.begin(), block_starts_.end()))
    throw std::logic_error("block relaxation: block starts must increase from 0");
  inverse_offsets_.assign(block_starts_.size(), 0);
  for (size_t block = 0; block + 1 < block_starts_.size(); ++block) {
    const long size = block_starts_[block + 1] - block_starts_[block];
    inverse_offsets_[block + 1] = inverse_offsets_[block] + size * size;
  }
  inverses_.resize(static_cast<size_t>(inverse_offsets_.back()));
}

void BlockRelaxationPreconditioner::compute(const Eigen::SparseMatrix<double>& matrix) {
  if (matrix.rows() != block_starts_.back())
    throw std::logic_error("block relaxation: matrix has " + std::to_string(matrix.rows()) + " rows, the blocks " +
                           std::to_string(block_starts_.back()));
  matrix_ = &matrix;
  const int blocks = block_count();
  std::atomic<int> failed{-1};
#pragma omp parallel for schedule(static)
  for (int block = 0; block < blocks; ++block) {
    const int first = block_starts_[block], size = block_starts_[block + 1] - first;
    Eigen::MatrixXd diagonal_block = Eigen::MatrixXd::Zero(size, size);
    for (int j = 0; j < size; ++j) {
      // The block's rows of column first + j: a run found by bisection (rows are sorted).
      const int* rows = matrix.innerIndexPtr() + matrix.outerIndexPtr()[first + j];
      const int* rows_end =
          rows + (matrix.isCompressed() ? matrix.outerIndexPtr()[first + j + 1] - matrix.outerIndexPtr()[first + j]
                                        : matrix.innerNonZeroPtr()[first + j]);
      const double* values = matrix.valuePtr() + matrix.outerIndexPtr()[first + j];
      for (const int* row = std::lower_bound(rows, rows_end, first); row != rows_end && *row < first + size; ++row)
        diagonal_block(*row - first, j) = values[row - rows];
    }
    const Eigen::LLT<Eigen::MatrixXd> cholesky(diagonal_block);
    if (cholesky.info() != Eigen::Success) {
      int expected = -1;
      failed.compare_exchange_strong(expected, block);
      continue;
    }
    Eigen::Map<Eigen::MatrixXd>(inverses_.data() + inverse_offsets_[block], size, size) =
        cholesky.solve(Eigen::MatrixXd::Identity(size, size));
  }
  if (failed >= 0)
    throw NumericalError("block relaxation: the diagonal block " + std::to_string(failed.load()) + " (DOFs " +
                         std::to_string(block_starts_[failed]) + "-" + std::to_string(block_starts_[failed + 1] - 1) +
                         ") is not positive definite");

  if (relaxation_ == BlockRelaxation::jacobi) return;
  // Which blocks' columns have identical rows (the relaxations of a vertex's 3 × 3 block read
  // x, or update the defect, once per row for them); uncompressed storage takes the
  // column-by-column path.
  same_rows_.assign(blocks, 0);
  if (matrix.isCompressed()) {
    const int* starts = matrix.outerIndexPtr();
    const int* rows = matrix.innerIndexPtr();
    for (int block = 0; block < blocks; ++block) {
      const int first = block_starts_[block];
      bool same = true;
      for (int column = first + 1; same && column < block_starts_[block + 1]; ++column)
        same = std::equal(rows + starts[column], rows + starts[column + 1], rows + starts[first],
                          rows + starts[first + 1]);
      same_rows_[block] = same;
    }
  }
  // One thread, or too few blocks to share: lexicographic sweeps (consecutive in memory, and
  // the stronger smoother); else multicolour ones, each colour's blocks in parallel.
  serial_ = omp_get_max_threads() == 1 || blocks < minimum_parallel_sweep_blocks;
  colour_starts_.assign(1, 0);
  blocks_by_colour_.clear();
  if (serial_) return;
  const std::vector<int> colour = colour_blocks(matrix, block_starts_);
  const int colours = blocks > 0 ? *std::max_element(colour.begin(), colour.end()) + 1 : 0;
  colour_starts_.assign(colours + 1, 0);
  for (int c : colour) ++colour_starts_[c + 1];
  for (int c = 0; c < colours; ++c) colour_starts_[c + 1] += colour_starts_[c];
  blocks_by_colour_.resize(blocks);
  std::vector<int> next(colour_starts_.begin(), colour_starts_.end() - 1);
  for (int block = 0; block < blocks; ++block) blocks_by_colour_[next[colour[block]]++] = block;
}

void BlockRelaxationPreconditioner::relax(int block, const Eigen::VectorXd& residual, Eigen::VectorXd& result) const {
  const int first = block_starts_[block], size = block_starts_[block + 1] - first;
  // (r − A x)_b from A's columns of the block (A = Aᵀ: column j is row j).
  if (size == 3 && same_rows_[block]) {
    // A vertex's three components: their columns share their rows, so x of each row is read
    // once for all three, the sums kept in registers.
    const int* starts = matrix_->outerIndexPtr();
    const int* rows = matrix_->innerIndexPtr();
    const double* values = matrix_->valuePtr();
    const int begin = starts[first], length = starts[first + 1] - begin;
    const double* column0 = values + begin;
    const double* column1 = values + starts[first + 1];
    const double* column2 = values + starts[first + 2];
    Eigen::Vector3d sums = residual.segment<3>(first);
    for (int k = 0; k < length; ++k) {
      const double x = result[rows[begin + k]];
      sums[0] -= column0[k] * x;
      sums[1] -= column1[k] * x;
      sums[2] -= column2[k] * x;
    }
    result.segment<3>(first) += Eigen::Map<const Eigen::Matrix3d>(inverses_.data() + inverse_offsets_[block]) * sums;
    return;
  }
  BlockScratch scratch(size);
  double* defect = scratch.data();
  for (int j = 0; j < size; ++j) {
    double sum = residual[first + j];
    for (Eigen::SparseMatrix<double>::InnerIterator entry(*matrix_, first + j); entry; ++entry)
      sum -= entry.value() * result[entry.row()];
    defect[j] = sum;
  }
  const Eigen::Map<const Eigen::MatrixXd> inverse(inverses_.data() + inverse_offsets_[block], size, size);
  result.segment(first, size).noalias() += inverse * Eigen::Map<const Eigen::VectorXd>(defect, size);
}

void BlockRelaxationPreconditioner::relax_updating(int block, Eigen::VectorXd& defect, Eigen::VectorXd& result) const {
  const int first = block_starts_[block], size = block_starts_[block + 1] - first;
  const int* starts = matrix_->outerIndexPtr();
  const int* rows = matrix_->innerIndexPtr();
  const double* values = matrix_->valuePtr();
  if (size == 3 && same_rows_[block]) {
    const Eigen::Vector3d change =
        Eigen::Map<const Eigen::Matrix3d>(inverses_.data() + inverse_offsets_[block]) * defect.segment<3>(first);
    result.segment<3>(first) += change;
    const int begin = starts[first], length = starts[first + 1] - begin;
    const double* column0 = values + begin;
    const double* column1 = values + starts[first + 1];
    const double* column2 = values + starts[first + 2];
    for (int k = 0; k < length; ++k)
      defect[rows[begin + k]] -= column0[k] * change[0] + column1[k] * change[1] + column2[k] * change[2];
    return;
  }
  BlockScratch scratch(size);
  double* change = scratch.data();
  const Eigen::Map<const Eigen::MatrixXd> inverse(inverses_.data() + inverse_offsets_[block], size, size);
  Eigen::Map<Eigen::VectorXd>(change, size).noalias() = inverse * defect.segment(first, size);
  result.segment(first, size) += Eigen::Map<const Eigen::VectorXd>(change, size);
  for (int j = 0; j < size; ++j)
    for (int k = starts[first + j]; k < starts[first + j + 1]; ++k) defect[rows[k]] -= values[k] * change[j];
}

void BlockRelaxationPreconditioner::sweep_forward(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const {
  if (serial_) {
    for (int block = 0; block < block_count(); ++block) relax(block, residual, result);
    return;
  }
  for (int c = 0; c < colour_count(); ++c) {
#pragma omp parallel for schedule(static)
    for (int k = colour_starts_[c]; k < colour_starts_[c + 1]; ++k) relax(blocks_by_colour_[k], residual, result);
  }
}

void BlockRelaxationPreconditioner::sweep_backward(bool after_forward, const Eigen::VectorXd& residual,
                                                   Eigen::VectorXd& result) const {
  // Right after a forward sweep, the blocks it relaxed last (the last block; in colour order
  // the whole last colour) saw their final neighbours: relaxing them again changes nothing.
  if (serial_) {
    for (int block = block_count() - 1 - (after_forward ? 1 : 0); block >= 0; --block) relax(block, residual, result);
    return;
  }
  for (int c = colour_count() - 1 - (after_forward ? 1 : 0); c >= 0; --c) {
#pragma omp parallel for schedule(static)
    for (int k = colour_starts_[c]; k < colour_starts_[c + 1]; ++k) relax(blocks_by_colour_[k], residual, result);
  }
}

void BlockRelaxationPreconditioner::apply(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const {
  result.resize(residual.size());
  if (relaxation_ == BlockRelaxation::jacobi) {
    const int blocks = block_count();
#pragma omp parallel for schedule(static) if (blocks >= minimum_parallel_blocks)
    for (int block = 0; block < blocks; ++block) {
      const int first = block_starts_[block], size = block_starts_[block + 1] - first;
      const Eigen::Map<const Eigen::MatrixXd> inverse(inverses_.data() + inverse_offsets_[block], size, size);
      result.segment(first, size).noalias() = inverse * residual.segment(first, size);
    }
    return;
  }
  result.setZero();
  sweep_forward(residual, result);
  if (relaxation_ == BlockRelaxation::symmetric_gauss_seidel) sweep_backward(true, residual, result);
}

bool BlockRelaxationPreconditioner::apply_with_defect(const Eigen::VectorXd& residual, Eigen::VectorXd& result,
                                                      Eigen::VectorXd& defect) const {
  if (relaxation_ == BlockRelaxation::jacobi || !serial_ || !matrix_->isCompressed()) return false;
  result.setZero(residual.size());
  defect = residual;
  for (int block = 0; block < block_count(); ++block) relax_updating(block, defect, result);
  if (relaxation_ == BlockRelaxation::symmetric_gauss_seidel)
    for (int block = block_count() - 2; block >= 0; --block) relax_updating(block, defect, result);
  return true;
}

void BlockRelaxationPreconditioner::apply_transpose(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const {
  if (relaxation_ != BlockRelaxation::gauss_seidel) {
    apply(residual, result);
    return;
  }
  result.setZero(residual.size());
  sweep_backward(false, residual, result);
}

}  // namespace altfem
