#pragma once
// The basis of every cell of a polyhedral mesh for the harmonic method (Martin et al.
// 2008 §4-5): nodal, so basis function i is mesh node i and neighbours share it; on a
// plain Tet4/Hex8 cell (with HarmonicBasisKind::automatic) the closed-form linear /
// trilinear basis, on every other cell the MFS harmonic basis, built in parallel over
// cells and kept for tabulation and for evaluation at points (embedding).
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "polyhedral/earlier_tabulation.hpp"
#include "polyhedral/element_harmonic_basis.hpp"
#include "polyhedral/harmonic_basis_memory.hpp"
#include "polyhedral/harmonic_cell_rule.hpp"
#include "polyhedral/harmonic_scene_block.hpp"
#include "polyhedral/plain_cells.hpp"
#include "shared/assembly/tabulated_elements.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem::harmonic {

class HarmonicElementBases;

/// A build's stiffness tabulation, for the build an event makes next to copy from: an MFS
/// cell the event left alone keeps its basis (harmonic_basis_memory.hpp) and so its points
/// (Martin et al. 2008 §8: only cut elements are new), copied, not evaluated again, its
/// nodes in the new mesh's order (earlier_tabulation.hpp). Valid while that build lives
/// (Simulation::rebuild_on builds the next one before it lets the old one go).
struct EarlierTabulation {
  const HarmonicElementBases* bases = nullptr;
  const TabulatedElements* elements = nullptr;  ///< tabulated by bases->tabulate(strength, …)
  int strength = 0;
};

class HarmonicElementBases {
public:
  /// Keeps a reference to `mesh`. Throws NumericalError naming the cell when an MFS fit
  /// is not finite. An MFS cell whose shape `previous` holds (an event's rebuild) takes
  /// that fit, moved, instead of a fit of its own (harmonic_basis_memory.hpp), and a cell
  /// alike to one fitted before it in this build takes that fit, moved; `remember`
  /// receives the shapes fitted, for the next rebuild. Over several ranks every rank builds
  /// it alike: each fits every count()-th cell to fit and the fits are gathered.
  HarmonicElementBases(const PolyhedralMesh& mesh, HarmonicBasisKind kind, const MfsOptions& options,
                       const HarmonicBasisMemory* previous = nullptr, HarmonicBasisMemory* remember = nullptr);

  int cell_count() const { return static_cast<int>(cells_.size()); }
  /// The cell's global basis (node) indices, in the order of its values.
  const std::vector<int>& nodes(int cell) const { return cells_[cell].nodes; }
  /// The closed-form element of a plain cell, or nullopt for an MFS cell.
  std::optional<ElementType> plain_type(int cell) const { return cells_[cell].plain; }
  /// The MFS basis of an MFS cell (nullptr for a plain cell).
  const ElementHarmonicBasis* mfs_basis(int cell) const { return cells_[cell].mfs ? &*cells_[cell].mfs : nullptr; }
  /// The largest RMS boundary misfit of the MFS fits (0 without MFS cells).
  double max_boundary_residual() const;
  /// The MFS cells whose basis came from the builds before (`previous`), not a fit.
  int remembered_bases() const { return remembered_bases_; }
  /// The MFS cells that took the fit of a translate or scaled copy of theirs in this build
  /// (cell_shape_key).
  int moved_bases() const { return moved_bases_; }

  /// Every cell tabulated with a rule of `strength`: tet_rule/hex_rule on plain cells,
  /// harmonic_cell_rule(quadrature) with harmonic_tabulation's consistency correction
  /// (when quadrature.consistent) on MFS cells. Element e is cell e, of material
  /// materials[e] (empty: all 0). Parallel over cells. Throws NumericalError naming the
  /// first MFS cell whose rule has no point (a cell thinner than a subdivision box). A cell
  /// `here` does not hold is added with its nodes and its rule's point count only
  /// (TabulatedElements::add_held_elsewhere): its basis is not evaluated, and its MFS rule is
  /// made only when `listed` (every cell's count, ElementTabulator) is not given. An MFS
  /// cell whose polyhedron and basis `earlier` holds (match_earlier_cells) takes its points
  /// from there when `earlier` was tabulated at this strength (its quadrature must be this
  /// one: the same scene's); `copied`, when given, counts those cells.
  TabulatedElements tabulate(int strength, const HarmonicQuadrature& quadrature, const std::vector<int>& materials = {},
                             const TabulatedHere& here = nullptr, const TabulatedElements* listed = nullptr,
                             const EarlierTabulation* earlier = nullptr, int* copied = nullptr) const;

  /// The cell's basis values at x (#nodes of the cell, in the order of nodes(cell)),
  /// extrapolated when x is outside: a plain cell through its inverse map (Newton), an
  /// MFS cell by its kernel expansion. Returns false when the inverse map fails (a
  /// degenerate cell: Mesh_3 leaves slivers).
  bool evaluate(int cell, const Eigen::Vector3d& x, Eigen::VectorXd& values) const;

  /// Every cell's nodes and basis, bit for bit (harmonic_basis_cache).
  void write(BinaryWriter& out) const;
  /// What write wrote for `mesh`, or nullopt when it does not read back whole, or not for
  /// as many cells and nodes as `mesh` has.
  static std::optional<HarmonicElementBases> read(const PolyhedralMesh& mesh, BinaryReader& in);

private:
  struct Cell {
    std::vector<int> nodes;
    std::optional<ElementType> plain;
    std::optional<ElementHarmonicBasis> mfs;
  };
  HarmonicElementBases(const PolyhedralMesh& mesh, std::vector<Cell> cells) : mesh_(mesh), cells_(std::move(cells)) {}
  /// Per cell, the cell of `earlier` whose tabulation it may copy (tabulate), and how.
  std::vector<EarlierCell> cells_tabulated_earlier(const EarlierTabulation* earlier, int strength,
                                                   const std::vector<char>& held) const;

  const PolyhedralMesh& mesh_;
  std::vector<Cell> cells_;
  int remembered_bases_ = 0;
  int moved_bases_ = 0;
};

}  // namespace altfem::harmonic
