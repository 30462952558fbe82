#include "polyhedral/harmonic_basis_memory.hpp"

#include <cmath>

#include "polyhedral/canonical_cell.hpp"
#include "shared/io/binary_cache.hpp"

namespace altfem::harmonic {

namespace {

bool same_options(const MfsOptions& a, const MfsOptions& b) {
  return a.edge_samples == b.edge_samples && a.collocation_factor == b.collocation_factor && a.offset == b.offset;
}

}  // namespace

CellShapeKey cell_shape_key(const PolyhedralMesh& mesh, int cell) {
  CanonicalCell canonical = canonical_cell(mesh, cell);
  CellShapeKey key;
  const Eigen::MatrixXd& vertices = canonical.polyhedron.vertices;
  key.anchor = vertices.row(0).transpose();
  const Eigen::MatrixX3d relative = vertices.rowwise() - key.anchor.transpose();
  const double size = (relative.colwise().maxCoeff() - relative.colwise().minCoeff()).norm();
  // A power of two, so translates whose sizes differ in the last bits still round alike,
  // and a copy scaled by a power of two has the same offsets in its own unit.
  key.unit = std::exp2(std::floor(std::log2(1e-9 * size)));
  key.offsets.reserve(static_cast<size_t>(3 * relative.rows()));
  for (Eigen::Index v = 0; v < relative.rows(); ++v)
    for (int d = 0; d < 3; ++d) key.offsets.push_back(std::llround(relative(v, d) / key.unit));
  key.structure.push_back(static_cast<int>(canonical.polyhedron.faces.size()));
  for (const std::vector<int>& face : canonical.polyhedron.faces) {
    key.structure.push_back(static_cast<int>(face.size()));
    key.structure.insert(key.structure.end(), face.begin(), face.end());
  }
  key.local = std::move(canonical.local);
  CacheKeyHasher hasher;
  hasher.bytes(key.offsets.data(), sizeof(std::int64_t) * key.offsets.size());
  hasher.bytes(key.structure.data(), sizeof(int) * key.structure.size());
  key.hash = hasher.value();
  return key;
}

ElementHarmonicBasis moved_basis(const ElementHarmonicBasis& basis, const CellShapeKey& from, const CellShapeKey& to) {
  // Node to.local[k] here is node from.local[k] there, both sorted by position.
  std::vector<int> order(to.local.size());
  for (size_t k = 0; k < order.size(); ++k) order[to.local[k]] = from.local[k];
  if (to.anchor == from.anchor && to.unit == from.unit) return basis.reordered(order);
  return basis.reordered(order).moved(from.anchor, to.anchor, to.unit / from.unit);
}

const HarmonicBasisMemory::Entry* HarmonicBasisMemory::entry(const CellShapeKey& key) const {
  const auto [first, last] = by_hash_.equal_range(key.hash);
  for (auto candidate = first; candidate != last; ++candidate)
    if (candidate->second->key == key) return candidate->second.get();
  return nullptr;
}

std::optional<ElementHarmonicBasis> HarmonicBasisMemory::find(const CellShapeKey& key,
                                                              const MfsOptions& options) const {
  if (!same_options(options, options_)) return std::nullopt;
  const Entry* held = entry(key);
  if (!held) return std::nullopt;
  return moved_basis(held->basis, held->key, key);
}

bool HarmonicBasisMemory::holds(const CellShapeKey& key, const MfsOptions& options) const {
  return same_options(options, options_) && entry(key) != nullptr;
}

void HarmonicBasisMemory::add(const CellShapeKey& key, const ElementHarmonicBasis& basis) {
  if (entry(key)) return;
  by_hash_.emplace(key.hash, std::make_shared<const Entry>(Entry{key, basis}));
}

}  // namespace altfem::harmonic
