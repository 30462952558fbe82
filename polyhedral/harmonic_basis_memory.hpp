#pragma once
// The MFS bases one build fitted, by the geometry of their cells, kept for the build an
// event rebuilds (a cut, a refinement): a cell the event left alone — its nodes where they
// were, in the same order, its faces the same loops — takes its basis bit for bit instead
// of being fitted again, so that only the cells the event changed get new bases (Martin et
// al. 2008 §8: "only cut elements" become polyhedra with new harmonic bases; issue #33).
// A neighbour of a cut cell is changed: the blade's crossings on its edges are new
// vertices of its faces.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "polyhedral/element_harmonic_basis.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem::harmonic {

/// What a cell's MFS basis is fitted from (mesh_face_coordinates, cell_harmonic_basis) —
/// its vertices and faces — whatever the mesh's numbering: a rebuilt mesh numbers its
/// nodes, faces and cells otherwise. Vertices sorted by position (compared bit for bit),
/// each face loop in that numbering from its lowest vertex (orientation kept), loops sorted.
struct CellGeometryKey {
  Eigen::MatrixX3d vertices;   ///< #nodes × 3, sorted
  std::vector<int> structure;  ///< face count, then each face's size and loop
  std::vector<int> local;      ///< per sorted vertex, its index in cell_polyhedron order
  std::uint64_t hash = 0;

  /// The same geometry (the numbering `local` aside).
  bool operator==(const CellGeometryKey& other) const {
    return hash == other.hash && structure == other.structure && vertices == other.vertices;
  }
};

CellGeometryKey cell_geometry_key(const PolyhedralMesh& mesh, int cell);

/// A cell's geometry up to translation and scaling by a power of two: the geometry key with
/// its vertices taken relative to the first (lowest) one, in units of a power of two near
/// 1e-9 of the cell's size, so that the cells a blade or a refinement makes alike across a
/// grid, and a refinement's levels make alike but halved, compare equal although their
/// coordinates round differently. Cells that share it are images of each other under
/// x ↦ anchor' + (unit'/unit)(x − anchor) to that accuracy, far inside any MFS fit's (1e-3
/// to 1e-2), and list their faces alike.
struct CellShapeKey {
  std::vector<std::int64_t> offsets;  ///< 3 per sorted vertex, in units of the rounding
  std::vector<int> structure;         ///< face count, then each face's size and loop as the cell lists them
  std::vector<int> local;             ///< as CellGeometryKey's
  Eigen::Vector3d anchor;             ///< the first sorted vertex
  double unit = 1;                    ///< the offsets' unit: a power of two
  std::uint64_t hash = 0;

  bool operator==(const CellShapeKey& other) const {
    return hash == other.hash && structure == other.structure && offsets == other.offsets;
  }
};

CellShapeKey cell_shape_key(const PolyhedralMesh& mesh, int cell);

class HarmonicBasisMemory {
public:
  explicit HarmonicBasisMemory(const MfsOptions& options) : options_(options) {}

  /// The basis fitted for a cell of this geometry with `options`, its nodes in the order
  /// of `key.local` (nullopt: none).
  std::optional<ElementHarmonicBasis> find(const CellGeometryKey& key, const MfsOptions& options) const;
  void add(CellGeometryKey key, const ElementHarmonicBasis& basis);
  int size() const { return static_cast<int>(entries_.size()); }

private:
  struct Entry {
    CellGeometryKey key;
    ElementHarmonicBasis basis;
  };
  MfsOptions options_;
  std::unordered_multimap<std::uint64_t, int> by_hash_;  // → entries_
  std::vector<Entry> entries_;
};

}  // namespace altfem::harmonic
