#pragma once
// The MFS fits of every cell shape a run has met, kept for the builds its events make (a
// cut, a refinement). A shape is a cell up to translation and scaling by a power of two
// (cell_shape_key): a cell the event left alone takes its basis bit for bit (the same fit
// moved the same way), and a new cell alike to one met before — a refinement's next level
// repeats its cells halved — takes that fit moved, so that only shapes new to the run are
// fitted (Martin et al. 2008 §8: "only cut elements" become polyhedra with new harmonic
// bases; issue #33). A neighbour of a cut cell is changed: the blade's crossings on its
// edges are new vertices of its faces.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "polyhedral/element_harmonic_basis.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem::harmonic {

/// A cell's geometry up to translation and scaling by a power of two, whatever the mesh's
/// numbering and however it lists the faces (canonical_cell): its sorted vertices relative
/// to the first (lowest) one, in units of a power of two near 1e-9 of the cell's size, so
/// that the cells a blade or a refinement makes alike across a grid, and a refinement's
/// levels make alike but halved, compare equal although their coordinates round
/// differently; and its canonical face loops. Cells that share it are images of each other
/// under x ↦ anchor' + (unit'/unit)(x − anchor) to that accuracy, far inside any MFS fit's
/// (1e-3 to 1e-2), and their canonical cells are sampled alike: fitted, they agree to
/// round-off.
struct CellShapeKey {
  std::vector<std::int64_t> offsets;  ///< 3 per sorted vertex, in units of `unit`
  std::vector<int> structure;         ///< face count, then each canonical face's size and loop
  std::vector<int> local;             ///< per sorted vertex, its index in cell_nodes order
  Eigen::Vector3d anchor;             ///< the first sorted vertex
  double unit = 1;                    ///< a power of two
  std::uint64_t hash = 0;

  bool operator==(const CellShapeKey& other) const {
    return hash == other.hash && structure == other.structure && offsets == other.offsets;
  }
};

CellShapeKey cell_shape_key(const PolyhedralMesh& mesh, int cell);

/// The basis `basis` of the cell keyed `from` (its nodes in cell_nodes order) moved to the
/// cell keyed `to`, of the same shape: its nodes matched by their sorted positions, moved
/// and scaled. The basis itself when `to` is `from`'s very cell.
ElementHarmonicBasis moved_basis(const ElementHarmonicBasis& basis, const CellShapeKey& from, const CellShapeKey& to);

class HarmonicBasisMemory {
public:
  explicit HarmonicBasisMemory(const MfsOptions& options) : options_(options) {}

  /// The basis fitted for a cell of this shape with `options`, moved to the cell `key`
  /// (nullopt: none).
  std::optional<ElementHarmonicBasis> find(const CellShapeKey& key, const MfsOptions& options) const;
  /// Whether it holds a fit for a cell of this shape with `options`.
  bool holds(const CellShapeKey& key, const MfsOptions& options) const;
  /// Keeps the fit of the cell `key` unless its shape is held already.
  void add(const CellShapeKey& key, const ElementHarmonicBasis& basis);
  /// The shapes held.
  int size() const { return static_cast<int>(by_hash_.size()); }

private:
  struct Entry {
    CellShapeKey key;
    ElementHarmonicBasis basis;
  };
  const Entry* entry(const CellShapeKey& key) const;

  MfsOptions options_;
  // Shared: the memory of the next build starts as a copy of this one.
  std::unordered_multimap<std::uint64_t, std::shared_ptr<const Entry>> by_hash_;
};

}  // namespace altfem::harmonic
