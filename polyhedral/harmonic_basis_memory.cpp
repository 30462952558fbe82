#include "polyhedral/harmonic_basis_memory.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "shared/geometry/polyhedron.hpp"
#include "shared/io/binary_cache.hpp"

namespace altfem::harmonic {

namespace {

bool same_options(const MfsOptions& a, const MfsOptions& b) {
  return a.edge_samples == b.edge_samples && a.collocation_factor == b.collocation_factor && a.offset == b.offset;
}

// A cell's polyhedron with its vertices ordered by position (lexicographically), which
// both keys number them by whatever the mesh's numbering.
struct PositionOrder {
  Polyhedron polyhedron;
  std::vector<int> local;   // per sorted vertex, its index in cell_polyhedron order
  std::vector<int> sorted;  // per local vertex, its sorted index
};

PositionOrder position_order(const PolyhedralMesh& mesh, int cell) {
  PositionOrder order{cell_polyhedron(mesh, cell), {}, {}};
  const Eigen::MatrixXd& vertices = order.polyhedron.vertices;
  const auto count = static_cast<int>(vertices.rows());
  order.local.resize(count);
  std::iota(order.local.begin(), order.local.end(), 0);
  std::sort(order.local.begin(), order.local.end(), [&](int a, int b) {
    const auto x = vertices.row(a), y = vertices.row(b);
    return std::lexicographical_compare(x.begin(), x.end(), y.begin(), y.end());
  });
  order.sorted.resize(count);
  for (int k = 0; k < count; ++k) order.sorted[order.local[k]] = k;
  return order;
}

}  // namespace

CellGeometryKey cell_geometry_key(const PolyhedralMesh& mesh, int cell) {
  PositionOrder order = position_order(mesh, cell);
  CellGeometryKey key;
  key.vertices = order.polyhedron.vertices(order.local, Eigen::all);
  std::vector<std::vector<int>> loops;
  for (const std::vector<int>& face : order.polyhedron.faces) {
    std::vector<int> loop;
    for (int vertex : face) loop.push_back(order.sorted[vertex]);
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    loops.push_back(std::move(loop));
  }
  std::sort(loops.begin(), loops.end());
  key.structure.push_back(static_cast<int>(loops.size()));
  for (const std::vector<int>& loop : loops) {
    key.structure.push_back(static_cast<int>(loop.size()));
    key.structure.insert(key.structure.end(), loop.begin(), loop.end());
  }
  key.local = std::move(order.local);
  CacheKeyHasher hasher;
  hasher.matrix(key.vertices);
  hasher.bytes(key.structure.data(), sizeof(int) * key.structure.size());
  key.hash = hasher.value();
  return key;
}

CellShapeKey cell_shape_key(const PolyhedralMesh& mesh, int cell) {
  PositionOrder order = position_order(mesh, cell);
  CellShapeKey key;
  const Eigen::MatrixXd& vertices = order.polyhedron.vertices;
  key.anchor = vertices.row(order.local.front()).transpose();
  const Eigen::MatrixX3d relative = vertices(order.local, Eigen::all).rowwise() - key.anchor.transpose();
  const double size = (relative.colwise().maxCoeff() - relative.colwise().minCoeff()).norm();
  // A power of two, so translates whose sizes differ in the last bits still round alike,
  // and a copy scaled by a power of two has the same offsets in its own unit.
  key.unit = std::exp2(std::floor(std::log2(1e-9 * size)));
  key.offsets.reserve(static_cast<size_t>(3 * relative.rows()));
  for (Eigen::Index v = 0; v < relative.rows(); ++v)
    for (int d = 0; d < 3; ++d) key.offsets.push_back(std::llround(relative(v, d) / key.unit));
  // The faces as the cell lists them, each loop from where the cell starts it: the fit
  // samples faces in this order from frames their loops set, and keeps the first of close
  // kernel centres, so cells that list them alike get the same samples, moved, and fits
  // that agree to round-off. Listed otherwise, the fits agree only to their accuracy (1e-4
  // on a box), and a moved basis would no longer share its faces' data with its
  // neighbours' (their face integrals cancel only when both read the same face function).
  key.structure.push_back(static_cast<int>(order.polyhedron.faces.size()));
  for (const std::vector<int>& face : order.polyhedron.faces) {
    key.structure.push_back(static_cast<int>(face.size()));
    for (int vertex : face) key.structure.push_back(order.sorted[vertex]);
  }
  key.local = std::move(order.local);
  CacheKeyHasher hasher;
  hasher.bytes(key.offsets.data(), sizeof(std::int64_t) * key.offsets.size());
  hasher.bytes(key.structure.data(), sizeof(int) * key.structure.size());
  key.hash = hasher.value();
  return key;
}

std::optional<ElementHarmonicBasis> HarmonicBasisMemory::find(const CellGeometryKey& key,
                                                              const MfsOptions& options) const {
  if (!same_options(options, options_)) return std::nullopt;
  const auto [first, last] = by_hash_.equal_range(key.hash);
  for (auto candidate = first; candidate != last; ++candidate) {
    const Entry& entry = entries_[candidate->second];
    if (!(entry.key == key)) continue;
    // Node key.local[k] here is node entry.key.local[k] there.
    std::vector<int> order(key.local.size());
    for (size_t k = 0; k < order.size(); ++k) order[key.local[k]] = entry.key.local[k];
    return entry.basis.reordered(order);
  }
  return std::nullopt;
}

void HarmonicBasisMemory::add(CellGeometryKey key, const ElementHarmonicBasis& basis) {
  by_hash_.emplace(key.hash, static_cast<int>(entries_.size()));
  entries_.push_back({std::move(key), basis});
}

}  // namespace altfem::harmonic
