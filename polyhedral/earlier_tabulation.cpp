#include "polyhedral/earlier_tabulation.hpp"

#include <cstdint>
#include <unordered_map>

#include "polyhedral/canonical_cell.hpp"
#include "shared/io/binary_cache.hpp"

namespace altfem::harmonic {

namespace {

// A cell in its canonical listing (canonical_cell: vertices sorted by position, loops from
// their lowest vertex, sorted), its exact vertices and loops hashed: a cell listed
// otherwise has the same canonical cell.
struct KeyedCell {
  CanonicalCell canonical;
  std::uint64_t key = 0;
  bool distinct = true;  ///< no two vertices at one position (a slit's two sides)
};

KeyedCell keyed_cell(const PolyhedralMesh& mesh, int cell) {
  KeyedCell keyed{canonical_cell(mesh, cell)};
  const Polyhedron& polyhedron = keyed.canonical.polyhedron;
  for (Eigen::Index v = 1; v < polyhedron.vertices.rows() && keyed.distinct; ++v)
    keyed.distinct = polyhedron.vertices.row(v) != polyhedron.vertices.row(v - 1);
  CacheKeyHasher hasher;
  hasher.matrix(polyhedron.vertices);
  for (const std::vector<int>& face : polyhedron.faces) {
    hasher.scalar<std::int64_t>(static_cast<std::int64_t>(face.size()));
    hasher.bytes(face.data(), face.size() * sizeof(int));
  }
  keyed.key = hasher.value();
  return keyed;
}

}  // namespace

std::vector<EarlierCell> match_earlier_cells(const PolyhedralMesh& mesh,
                                             const std::vector<const ElementHarmonicBasis*>& bases,
                                             const std::vector<char>& candidate, const PolyhedralMesh& earlier_mesh,
                                             const std::vector<const ElementHarmonicBasis*>& earlier_bases,
                                             const std::vector<char>& earlier_candidate) {
  const int earlier_count = earlier_mesh.cell_count();
  std::vector<KeyedCell> earlier(static_cast<std::size_t>(earlier_count));
#pragma omp parallel for schedule(dynamic, 16)
  for (int cell = 0; cell < earlier_count; ++cell)
    if (earlier_bases[cell] && earlier_candidate[cell]) earlier[cell] = keyed_cell(earlier_mesh, cell);
  std::unordered_multimap<std::uint64_t, int> by_key;
  for (int cell = 0; cell < earlier_count; ++cell)
    if (!earlier[cell].canonical.polyhedron.faces.empty() && earlier[cell].distinct)
      by_key.emplace(earlier[cell].key, cell);
  std::vector<EarlierCell> result(static_cast<std::size_t>(mesh.cell_count()));
  if (by_key.empty()) return result;
#pragma omp parallel for schedule(dynamic, 16)
  for (int cell = 0; cell < mesh.cell_count(); ++cell) {
    if (!bases[cell] || !candidate[cell]) continue;
    const KeyedCell here = keyed_cell(mesh, cell);
    if (!here.distinct) continue;
    const auto [first, last] = by_key.equal_range(here.key);
    for (auto match = first; match != last; ++match) {
      const CanonicalCell& there = earlier[match->second].canonical;
      if (here.canonical.polyhedron.vertices != there.polyhedron.vertices ||
          here.canonical.polyhedron.faces != there.polyhedron.faces)
        continue;
      // Sorted vertex k is local node here.local[k] here and there.local[k] there.
      std::vector<int> order(here.canonical.local.size());
      for (std::size_t k = 0; k < order.size(); ++k) order[here.canonical.local[k]] = there.local[k];
      if (earlier_bases[match->second]->reordered(order).content_key() != bases[cell]->content_key()) continue;
      result[cell] = {match->second, std::move(order)};
      break;
    }
  }
  return result;
}

}  // namespace altfem::harmonic
