#pragma once
// Embedding of surface points in topology-aware finite cells: the copies of a split
// background cell overlap in space, so a point that lies in the cell belongs to the
// piece whose material is nearest to it (a surface vertex lies on its own piece's
// boundary, and only approximately when Mesh_3 meshed the surface).
#include <Eigen/Geometry>
#include <limits>
#include <memory>
#include <unsupported/Eigen/BVH>
#include <vector>

#include "shared/cut_cells/piece_mesh.hpp"
#include "shared/fem/lagrange_basis_evaluator.hpp"

namespace altfem {

class PieceBasisEvaluator final : public ElementBasisEvaluator {
public:
  /// mesh: the kept cells (basis function i = node i), kept_rows: per kept cell its row
  /// in `pieces`; embedded: the Tet4 mesh the pieces' tetrahedra index; constraints: the
  /// kept hanging nodes (null: none). Keeps references to mesh, embedded and constraints.
  PieceBasisEvaluator(const VolumeMesh& mesh, const PieceMesh& pieces, const std::vector<int>& kept_rows,
                      const VolumeMesh& embedded, const NodeConstraints* constraints = nullptr);

  int element_count() const override { return whole_.element_count(); }
  Eigen::AlignedBox3d element_bounds(int cell) const override { return whole_.element_bounds(cell); }
  /// As LagrangeBasisEvaluator, and for a cell of a split background cell only when its
  /// piece is (one of) the nearest of the kept pieces of that background cell.
  bool evaluate_inside(int cell, const Eigen::Vector3d& x, std::vector<int>& basis,
                       std::vector<double>& values) const override;
  double evaluate_nearest(const Eigen::Vector3d& x, std::vector<int>& basis,
                          std::vector<double>& values) const override {
    return whole_.evaluate_nearest(x, basis, values);
  }
  /// The whole cell's key, and for a piece of a split background cell its tetrahedra
  /// (their corners, in any order): they decide which of the cell's pieces is nearest.
  std::uint64_t element_key(int cell) const override;
  void element_functions(int cell, std::vector<int>& basis) const override { whole_.element_functions(cell, basis); }
  /// A piece of a split background cell holds x whatever its cell's other pieces are
  /// where x lies on or in its tetrahedra: none is nearer. Then a piece of the cell before
  /// it rejects x by its own distance to x (its key), and a piece of another cell before
  /// it by that cell's geometry, since the pieces of one background cell come one after
  /// the other in index order.
  bool holds_alone(int cell, const Eigen::Vector3d& x) const override {
    return split_cell_[cell] < 0 || distance_to(piece_trees_[cell], x, std::numeric_limits<double>::denorm_min()) == 0;
  }
  /// A piece of the holder's background cell rejects x where its tetrahedra lie off x: the
  /// holder, on or around x, is nearer (a search of this piece's tetrahedra alone, not of
  /// the cell's: after a cut near a pencil's tip its chips' vertices ask this of the tip).
  bool rejects(int cell, int holder, const Eigen::Vector3d& x) const override {
    if (split_cell_[cell] < 0 || split_cell_[cell] != split_cell_[holder])
      return ElementBasisEvaluator::rejects(cell, holder, x);
    return distance_to(piece_trees_[cell], x, std::numeric_limits<double>::denorm_min()) > 0;
  }

private:
  /// Distance from x to the nearest tetrahedron of `tree` where it is below `bound`, else
  /// some value ≥ bound: a branch and bound over the tree of tetrahedron boxes, nearest box
  /// first, never opening a box at `bound` or beyond the nearest distance found. A cell
  /// near a pencil's tip holds thousands of tetrahedra and dozens of pieces (the chips),
  /// and every surface vertex in it asks: a scan of them all, piece by piece, was most of
  /// a cut's time.
  /// `nearest` (optional): the tetrahedron at that distance, or −1 where it is ≥ bound.
  double distance_to(const Eigen::KdBVH<double, 3, int>& tree, const Eigen::Vector3d& x, double bound,
                     int* nearest = nullptr) const;
  /// The kept cell of split background cell `split_cell` that holds `tetrahedron`.
  int piece_of(int split_cell, int tetrahedron) const;

  LagrangeBasisEvaluator whole_;
  const VolumeMesh& embedded_;
  long serial_;  ///< this evaluator's number, unique in the process
  /// Eigen's bounding volume hierarchies of tetrahedron boxes: per kept cell of a split
  /// background cell its piece's tetrahedra (empty otherwise), and per split background
  /// cell all its kept pieces' tetrahedra.
  std::vector<Eigen::KdBVH<double, 3, int>> piece_trees_, split_cell_trees_;
  std::vector<int> split_cell_;  ///< per kept cell: its split background cell's tree, or −1
  /// Per kept cell of a split background cell, a hash of its piece's tetrahedra (0 otherwise).
  std::vector<std::uint64_t> piece_keys_;
  /// Per split background cell, (tetrahedron, kept cell) of its pieces, sorted.
  std::vector<std::vector<std::pair<int, int>>> split_cell_pieces_;
};

/// Distance from x to the closed tetrahedron (4 × 3 corners), 0 within 1e-12 of it in
/// barycentric coordinates. With `below` the least positive double (the caller asks only
/// whether x is in it), `below` for a point outside, its faces not measured.
double distance_to_tetrahedron(const Eigen::Vector3d& x, const Eigen::Matrix<double, 4, 3>& corners,
                               double below = std::numeric_limits<double>::infinity());

}  // namespace altfem
