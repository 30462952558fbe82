#include "shared/solve/additive_schwarz_preconditioner.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

#include "shared/common/eigen_decompositions.hpp"
#include "shared/common/error.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem {

AdditiveSchwarzPreconditioner::AdditiveSchwarzPreconditioner(std::vector<std::vector<int>> blocks, double epsilon)
    : blocks_(std::move(blocks)), epsilon_(epsilon) {
  for (auto& block : blocks_) {
    std::sort(block.begin(), block.end());
    block.erase(std::unique(block.begin(), block.end()), block.end());
  }
  inverses_.resize(blocks_.size());
  gathered_.resize(blocks_.size());
  products_.resize(blocks_.size());
  for (size_t k = 0; k < blocks_.size(); ++k) {
    gathered_[k].resize(static_cast<Eigen::Index>(blocks_[k].size()));
    products_[k].resize(static_cast<Eigen::Index>(blocks_[k].size()));
  }
}

void AdditiveSchwarzPreconditioner::gather(const Eigen::SparseMatrix<double>& matrix,
                                           std::vector<Eigen::MatrixXd>& blocks, Eigen::VectorXd& diagonal) const {
  diagonal = matrix.diagonal();
  blocks.resize(blocks_.size());
#pragma omp parallel for schedule(dynamic, 4)
  for (size_t k = 0; k < blocks_.size(); ++k) {
    const auto& block = blocks_[k];
    const auto n = static_cast<Eigen::Index>(block.size());
    // C_K: for each of the block's columns, the entries whose rows are in the block.
    Eigen::MatrixXd& local = blocks[k];
    local.setZero(n, n);
    for (Eigen::Index j = 0; j < n; ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, block[j]); entry; ++entry) {
        const auto found = std::lower_bound(block.begin(), block.end(), static_cast<int>(entry.row()));
        if (found != block.end() && *found == entry.row()) local(found - block.begin(), j) = entry.value();
      }
  }
}

void AdditiveSchwarzPreconditioner::compute(const Eigen::SparseMatrix<double>& matrix) {
  std::vector<Eigen::MatrixXd> blocks;
  Eigen::VectorXd diagonal;
  gather(matrix, blocks, diagonal);
  decompose(blocks, diagonal);
}

void AdditiveSchwarzPreconditioner::compute_from_shares(const Eigen::SparseMatrix<double>& share) {
  std::vector<Eigen::MatrixXd> blocks;
  Eigen::VectorXd diagonal;
  gather(share, blocks, diagonal);
  // One sum over the ranks of the diagonal and every block, packed one after another.
  std::vector<double> packed(diagonal.data(), diagonal.data() + diagonal.size());
  for (const Eigen::MatrixXd& block : blocks) packed.insert(packed.end(), block.data(), block.data() + block.size());
  ranks::sum(packed);
  const double* next = packed.data();
  diagonal = Eigen::Map<const Eigen::VectorXd>(next, diagonal.size()), next += diagonal.size();
  for (Eigen::MatrixXd& block : blocks)
    block = Eigen::Map<const Eigen::MatrixXd>(next, block.rows(), block.cols()), next += block.size();
  decompose(blocks, diagonal);
}

void AdditiveSchwarzPreconditioner::decompose(std::vector<Eigen::MatrixXd>& blocks, const Eigen::VectorXd& diagonal) {
  const Eigen::Index dofs = diagonal.size();
  std::vector<int> in_block(static_cast<size_t>(dofs), 0);
  for (const auto& block : blocks_)
    for (int dof : block) ++in_block[dof];
  largest_overlap_ = std::max(1, *std::max_element(in_block.begin(), in_block.end()));
  diagonal_inverse_ = Eigen::VectorXd::Zero(dofs);
  for (Eigen::Index dof = 0; dof < dofs; ++dof) {
    if (in_block[dof]) continue;
    if (diagonal[dof] == 0.0)
      throw NumericalError("Additive-Schwarz preconditioner: diagonal entry of row " + std::to_string(dof) +
                           " is zero");
    diagonal_inverse_[dof] = 1.0 / std::abs(diagonal[dof]);
  }

  std::atomic<int> failed_block{-1}, small{0};
#pragma omp parallel for schedule(dynamic, 4)
  for (size_t k = 0; k < blocks_.size(); ++k) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(blocks[k]);
    const double largest = eigen.info() == Eigen::Success ? eigen.eigenvalues().cwiseAbs().maxCoeff() : 0.0;
    if (!(largest > 0)) {
      int expected = -1;
      failed_block.compare_exchange_strong(expected, static_cast<int>(k));
      continue;
    }
    const auto n = eigen.eigenvalues().size();
    Eigen::VectorXd reflected(n);
    int replaced = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double magnitude = std::abs(eigen.eigenvalues()[i]);
      if (magnitude >= epsilon_ * largest) {
        reflected[i] = 1.0 / magnitude;
      } else {
        reflected[i] = epsilon_ / largest;  // eq. (14)
        ++replaced;
      }
    }
    small += replaced;
    inverses_[k] = eigen.eigenvectors() * reflected.asDiagonal() * eigen.eigenvectors().transpose();
  }
  if (failed_block >= 0)
    throw NumericalError("Additive-Schwarz preconditioner: block " + std::to_string(failed_block.load()) +
                         " has no usable eigen-decomposition (zero or non-finite submatrix)");
  small_eigenvalues_ = small;
}

void AdditiveSchwarzPreconditioner::apply(const Eigen::VectorXd& residual, Eigen::VectorXd& result) const {
  result = diagonal_inverse_.cwiseProduct(residual);
  for (size_t k = 0; k < blocks_.size(); ++k) {
    const auto& block = blocks_[k];
    for (size_t i = 0; i < block.size(); ++i) gathered_[k][static_cast<Eigen::Index>(i)] = residual[block[i]];
    products_[k].noalias() = inverses_[k] * gathered_[k];
    for (size_t i = 0; i < block.size(); ++i) result[block[i]] += products_[k][static_cast<Eigen::Index>(i)];
  }
}

}  // namespace altfem
