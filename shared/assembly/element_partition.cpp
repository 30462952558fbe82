#include "shared/assembly/element_partition.hpp"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>

#include "shared/solve/process_ranks.hpp"

namespace altfem {
namespace {

PartitionGraph element_graph(const TabulatedElements& elements, const BasisGroups& couplings) {
  // The elements of each basis function.
  std::vector<std::vector<int>> holders(static_cast<size_t>(elements.basis_count()));
  for (int e = 0; e < elements.size(); ++e)
    for (int basis : elements[e].basis) holders[basis].push_back(e);
  std::vector<std::vector<int>> adjacent(static_cast<size_t>(elements.size()));
  const auto connect_all = [&](const std::vector<int>& group) {
    for (int first : group)
      for (int second : group)
        if (first != second) adjacent[first].push_back(second);
  };
  for (const std::vector<int>& group : holders) connect_all(group);
  std::vector<int> group_elements;
  for (int g = 0; g < couplings.size(); ++g) {
    group_elements.clear();
    for (int basis : couplings[g])
      if (basis < elements.basis_count())
        group_elements.insert(group_elements.end(), holders[basis].begin(), holders[basis].end());
    std::sort(group_elements.begin(), group_elements.end());
    group_elements.erase(std::unique(group_elements.begin(), group_elements.end()), group_elements.end());
    connect_all(group_elements);
  }
  return compressed_graph(std::move(adjacent));
}

}  // namespace

std::vector<int> partition_elements(const TabulatedElements& elements, const BasisGroups& couplings, int parts) {
  // An element's assembly costs about points × functions² flops; points × functions keeps
  // the weights small while ranking cut cells (many points) above plain ones.
  std::vector<double> work(static_cast<size_t>(elements.size()));
  for (int e = 0; e < elements.size(); ++e)
    work[e] = static_cast<double>(elements.whole_point_count(e)) * elements[e].basis_count();
  return partition_graph([&] { return element_graph(elements, couplings); }, work, parts);
}

}  // namespace altfem
