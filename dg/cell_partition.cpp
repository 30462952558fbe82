#include "dg/cell_partition.hpp"

#include <utility>

#include "shared/assembly/element_partition.hpp"

namespace altfem::dg {

std::vector<int> partition_cells(const std::vector<Polyhedron>& cells, const std::vector<MonomialBasis>& bases,
                                 const std::vector<std::array<int, 2>>& couplings, int parts) {
  std::vector<double> work(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const double functions = bases[c].size();
    work[c] = functions * functions * static_cast<double>(1 + cells[c].faces.size());
  }
  const auto graph = [&] {
    std::vector<std::vector<int>> adjacent(cells.size());
    for (const auto& [first, second] : couplings) {
      if (first == second) continue;
      adjacent[first].push_back(second);
      adjacent[second].push_back(first);
    }
    return compressed_graph(std::move(adjacent));
  };
  return partition_graph(graph, work, parts);
}

}  // namespace altfem::dg
