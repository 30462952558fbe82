#include "polyhedral/earlier_tabulation.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include "shared/io/binary_cache.hpp"

namespace altfem::harmonic {

namespace {

// A cell as listed, its local vertices sorted by position (lexicographic coordinates) and
// those positions hashed: a cell listed otherwise sorts to the same positions.
struct ListedCell {
  Polyhedron polyhedron;
  std::vector<int> by_position;
  std::uint64_t key = 0;
  bool distinct = true;  ///< no two vertices at one position (a slit's two sides)
};

ListedCell listed_cell(const PolyhedralMesh& mesh, int cell) {
  ListedCell listed{cell_polyhedron(mesh, cell)};
  const Eigen::MatrixXd& vertices = listed.polyhedron.vertices;
  listed.by_position.resize(static_cast<std::size_t>(vertices.rows()));
  std::iota(listed.by_position.begin(), listed.by_position.end(), 0);
  const auto position = [&](int vertex) {
    return std::array<double, 3>{vertices(vertex, 0), vertices(vertex, 1), vertices(vertex, 2)};
  };
  std::sort(listed.by_position.begin(), listed.by_position.end(),
            [&](int a, int b) { return position(a) < position(b); });
  CacheKeyHasher hasher;
  for (std::size_t k = 0; k < listed.by_position.size(); ++k) {
    const std::array<double, 3> here = position(listed.by_position[k]);
    if (k > 0 && here == position(listed.by_position[k - 1])) listed.distinct = false;
    for (const double coordinate : here) hasher.scalar(coordinate);
  }
  listed.key = hasher.value();
  return listed;
}

// The face loops with each vertex taken through `order` (none: as they are), each loop
// started at its smallest vertex (its orientation kept), the loops sorted: equal for the
// same oriented faces however listed.
std::vector<std::vector<int>> canonical_loops(const std::vector<std::vector<int>>& faces,
                                              const std::vector<int>* order) {
  std::vector<std::vector<int>> loops;
  loops.reserve(faces.size());
  for (const std::vector<int>& face : faces) {
    std::vector<int> loop = face;
    if (order)
      for (int& vertex : loop) vertex = (*order)[vertex];
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    loops.push_back(std::move(loop));
  }
  std::sort(loops.begin(), loops.end());
  return loops;
}

// The node order taking `here` onto `there` (per local vertex of here, there's at the same
// position), or empty when their positions differ.
std::vector<int> order_onto(const ListedCell& here, const ListedCell& there) {
  if (here.by_position.size() != there.by_position.size()) return {};
  std::vector<int> order(here.by_position.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const int mine = here.by_position[k], theirs = there.by_position[k];
    if (here.polyhedron.vertices.row(mine) != there.polyhedron.vertices.row(theirs)) return {};
    order[mine] = theirs;
  }
  return order;
}

}  // namespace

std::vector<EarlierCell> match_earlier_cells(const PolyhedralMesh& mesh,
                                             const std::vector<const ElementHarmonicBasis*>& bases,
                                             const std::vector<char>& candidate, const PolyhedralMesh& earlier_mesh,
                                             const std::vector<const ElementHarmonicBasis*>& earlier_bases,
                                             const std::vector<char>& earlier_candidate) {
  const int earlier_count = earlier_mesh.cell_count();
  std::vector<ListedCell> earlier(static_cast<std::size_t>(earlier_count));
#pragma omp parallel for schedule(dynamic, 16)
  for (int cell = 0; cell < earlier_count; ++cell)
    if (earlier_bases[cell] && earlier_candidate[cell]) earlier[cell] = listed_cell(earlier_mesh, cell);
  std::unordered_multimap<std::uint64_t, int> by_key;
  for (int cell = 0; cell < earlier_count; ++cell)
    if (!earlier[cell].polyhedron.faces.empty() && earlier[cell].distinct) by_key.emplace(earlier[cell].key, cell);
  std::vector<EarlierCell> result(static_cast<std::size_t>(mesh.cell_count()));
  if (by_key.empty()) return result;
#pragma omp parallel for schedule(dynamic, 16)
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    if (!bases[cell] || !candidate[cell]) continue;
    const ListedCell here = listed_cell(mesh, cell);
    if (!here.distinct) continue;
    const auto [first, last] = by_key.equal_range(here.key);
    for (auto match = first; match != last; ++match) {
      const ListedCell& there = earlier[match->second];
      std::vector<int> order = order_onto(here, there);
      if (order.empty() ||
          canonical_loops(here.polyhedron.faces, &order) != canonical_loops(there.polyhedron.faces, nullptr) ||
          earlier_bases[match->second]->reordered(order).content_key() != bases[cell]->content_key())
        continue;
      result[cell] = {match->second, std::move(order)};
      break;
    }
  }
  return result;
}

}  // namespace altfem::harmonic
