#include "shared/solve/identical_pattern_classes.hpp"

#include <cstdint>
#include <cstring>
#include <unordered_map>

namespace altfem {

std::vector<int> identical_pattern_classes(const int* outer, const int* inner, const std::vector<char>& kept,
                                           int& class_count) {
  const int column_count = static_cast<int>(kept.size());
  std::vector<std::uint64_t> hashes(static_cast<size_t>(column_count));
  // A sum of mixed row indices: no multiply chain through the column; the comparison below
  // then checks the rows as sequences (grouping needs the same order, not just the same set).
  for (int column = 0; column < column_count; ++column) {
    if (!kept[column]) continue;
    std::uint64_t hash = static_cast<std::uint64_t>(outer[column + 1] - outer[column]) * 0x9e3779b97f4a7c15ull;
    for (int at = outer[column]; at < outer[column + 1]; ++at) {
      const std::uint64_t row = static_cast<std::uint64_t>(inner[at]) * 0xff51afd7ed558ccdull;
      hash += row ^ (row >> 29);
    }
    hashes[column] = hash;
  }
  std::vector<int> classes(static_cast<size_t>(column_count), -1);
  std::unordered_map<std::uint64_t, int> first_column_of_hash;
  first_column_of_hash.reserve(static_cast<size_t>(column_count));
  class_count = 0;
  for (int column = 0; column < column_count; ++column) {
    if (!kept[column]) continue;
    const auto [found, added] = first_column_of_hash.try_emplace(hashes[column], column);
    const int first = found->second;
    if (!added && outer[first + 1] - outer[first] == outer[column + 1] - outer[column] &&
        std::memcmp(inner + outer[first], inner + outer[column],
                    sizeof(int) * static_cast<size_t>(outer[column + 1] - outer[column])) == 0)
      classes[column] = classes[first];
    else classes[column] = class_count++;
  }
  return classes;
}

}  // namespace altfem
