#include "shared/solve/partitioned_rows.hpp"

#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>

#include "shared/solve/graph_partition.hpp"
#include "shared/solve/process_ranks.hpp"

namespace altfem {

// The blocks sorted by a hash of their first column's rows; within one hash, a group per
// distinct list of rows.
std::vector<int> equal_column_groups(const Eigen::SparseMatrix<double>& matrix, int block, int& groups) {
  // The rows of a block's first column, read in place (the Hessians are compressed).
  Eigen::SparseMatrix<double> compressed;
  const Eigen::SparseMatrix<double>* pattern = &matrix;
  if (!matrix.isCompressed()) {
    compressed = matrix;
    compressed.makeCompressed();
    pattern = &compressed;
  }
  const auto rows = [&](Eigen::Index b) {
    const int* start = pattern->innerIndexPtr() + pattern->outerIndexPtr()[b * block];
    return std::span<const int>(start, pattern->innerIndexPtr() + pattern->outerIndexPtr()[b * block + 1]);
  };
  const Eigen::Index blocks = matrix.cols() / block;
  std::vector<std::pair<std::uint64_t, int>> keys(static_cast<size_t>(blocks));
  for (Eigen::Index b = 0; b < blocks; ++b) {
    std::uint64_t hash = 1469598103934665603ull;  // FNV-1a over the rows
    for (const int row : rows(b)) hash = (hash ^ static_cast<std::uint64_t>(row)) * 1099511628211ull;
    keys[b] = {hash, static_cast<int>(b)};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<int> group(static_cast<size_t>(blocks), -1);
  groups = 0;
  for (size_t begin = 0, end = 0; begin < keys.size(); begin = end) {
    end = begin;
    while (end < keys.size() && keys[end].first == keys[begin].first) ++end;
    for (size_t i = begin; i < end; ++i) {
      const int b = keys[i].second;
      if (group[b] >= 0) continue;
      group[b] = groups;
      for (size_t j = i + 1; j < end; ++j)
        if (group[keys[j].second] < 0 && std::ranges::equal(rows(keys[j].second), rows(b)))
          group[keys[j].second] = groups;
      ++groups;
    }
  }
  return group;
}

PartitionedRows partitioned_rows(const Eigen::SparseMatrix<double>& matrix, int block) {
  const Eigen::Index blocks = matrix.cols() / block;
  // The graph of the blocks' groups, each weighted by its blocks.
  int groups = 0;
  const std::vector<int> group = equal_column_groups(matrix, block, groups);
  std::vector<double> weights(static_cast<size_t>(groups), 0.0);
  for (const int g : group) weights[g] += 1.0;
  const std::vector<int> group_part = partition_graph(
      [&] {
        std::vector<std::vector<int>> adjacent(static_cast<size_t>(groups));
        for (Eigen::Index first = 0; first < blocks; ++first)
          for (Eigen::SparseMatrix<double>::InnerIterator entry(matrix, first * block); entry; ++entry)
            if (const int second = group[entry.row() / block]; second != group[first]) {
              adjacent[group[first]].push_back(second);
              adjacent[second].push_back(group[first]);
            }
        return compressed_graph(std::move(adjacent));
      },
      weights, ranks::count());
  // Blocks in order of their part, then of their index.
  std::vector<long long> first_of_part(static_cast<size_t>(ranks::count()) + 1, 0);
  for (Eigen::Index b = 0; b < blocks; ++b) ++first_of_part[group_part[group[b]] + 1];
  for (int p = 0; p < ranks::count(); ++p) first_of_part[p + 1] += first_of_part[p];
  PartitionedRows rows;
  rows.first_row = block * first_of_part[ranks::index()];
  rows.last_row = block * first_of_part[ranks::index() + 1];
  rows.new_of_old.resize(static_cast<size_t>(matrix.rows()));
  rows.old_of_new.resize(static_cast<size_t>(matrix.rows()));
  for (Eigen::Index b = 0; b < blocks; ++b) {
    const long long placed = first_of_part[group_part[group[b]]]++;
    for (int k = 0; k < block; ++k) {
      rows.new_of_old[block * b + k] = block * placed + k;
      rows.old_of_new[block * placed + k] = block * b + k;
    }
  }
  return rows;
}

}  // namespace altfem
