#pragma once
// A structured hexahedral grid refined 1→8 cell by cell, kept 2:1 balanced, and the
// conforming Lagrange mesh it makes, hanging nodes constrained (a forest of octrees over one
// box, as deal.II's and p4est's; issue #34's fem refinement). Every leaf is addressed on an
// integer lattice, so each decision — where a node is, which leaf holds a point, whether a
// node is also a neighbour's — is integer arithmetic, exact.
#include <Eigen/Geometry>
#include <vector>

#include "shared/element/element_type.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/cell_face_contact.hpp"
#include "shared/mesh/node_constraints.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// The deepest a grid cell can be split.
inline constexpr int max_forest_level = 10;
/// Lattice units per grid cell along each axis: the finest cell's half, where a quadratic
/// cell has its mid-edge nodes.
inline constexpr int forest_units_per_cell = 2 << max_forest_level;

/// The leaves of a structured grid (structured_grid's box, resolution and hexahedral type)
/// some of whose cells are split into eighths, their eighths again, and so on.
struct HexahedralForest {
  Eigen::AlignedBox3d box;
  Eigen::Vector3i resolution = Eigen::Vector3i::Ones();
  ElementType type = ElementType::hex8;
  std::vector<Eigen::Vector3i> origins;  ///< #leaves lower corners, in lattice units
  std::vector<int> levels;               ///< #leaves: 0 a grid cell, l + 1 an eighth of level l

  int leaf_count() const { return static_cast<int>(levels.size()); }
  /// A leaf's edge in lattice units.
  static int edge_units(int level) { return forest_units_per_cell >> level; }
  /// A lattice point's position in space.
  Eigen::Vector3d position(const Eigen::Vector3i& lattice) const;
};

/// The unsplit grid, its leaves in structured_grid's cell order (x fastest, then y, z).
/// Throws std::invalid_argument for a hexahedral type other than hex8, hex20, hex27, or an
/// empty box or resolution.
HexahedralForest grid_forest(const Eigen::AlignedBox3d& box, const Eigen::Vector3i& resolution, ElementType type);

/// Leaves out the leaves `keep` (a flag per leaf) does not keep: a grid over a shape built
/// of boxes keeps its cells inside the shape. What is left is refined, balanced and meshed
/// like any forest; where a leaf is missing is outside.
void keep_leaves(HexahedralForest& forest, const std::vector<bool>& keep);

/// `forest` with the `marked` leaves (indices) split into their eighths — children in place
/// of their parent, x fastest — and then every leaf that a face or edge neighbour more than
/// one level finer touches split too, until none does: the 2:1 balance under which each
/// hanging node's constraint reaches only one level up. `balancing_splits` (if given)
/// receives how many splits the balance added. Throws std::invalid_argument for a marked leaf
/// at max_forest_level.
HexahedralForest refine_forest(const HexahedralForest& forest, const std::vector<int>& marked,
                               int* balancing_splits = nullptr);

/// The forest as a Lagrange mesh of its type, one cell per leaf in leaf order, nodes shared
/// by lattice position. A node on a leaf's face or edge that is not a node of the coarser
/// leaf across it is hanging: its values are that leaf's interpolation at it (substituted
/// until every master is free), which keeps the space conforming and, since a child's space
/// holds its parent's polynomials, nested under refinement.
/// A leaf touching a hanging node that does not have it as a node, and that leaf's
/// interpolation at it: its nodes (some may hang themselves) and weights.
struct HangingNodeSource {
  int leaf = 0;
  std::vector<int> masters;
  std::vector<double> weights;
};
/// Per hanging node (constraints' order), every leaf it hangs on, coarsest first, before
/// hanging masters are substituted. A method that keeps only some cells (fcm) constrains
/// a node to the first of them it keeps, and leaves it free where it keeps none: there is
/// nothing to conform to.
using HangingNodeSources = std::vector<std::vector<HangingNodeSource>>;

struct ConstrainedHexahedralMesh {
  VolumeMesh mesh;  ///< free nodes first, then the hanging ones
  NodeConstraints constraints;
  HangingNodeSources sources;
};
ConstrainedHexahedralMesh forest_mesh(const HexahedralForest& forest);

/// One face two leaves share (the finer one's, where their levels differ).
struct ForestFace {
  int first = 0, second = 0;  ///< leaves
  double area = 0;
  int axis = 0;  ///< the face's normal is this coordinate axis
  int side = 1;  ///< +1: `second` lies on the side of `first` where that coordinate grows; −1: below
};
/// Every face between two leaves, each once.
std::vector<ForestFace> forest_interior_faces(const HexahedralForest& forest);
/// The same faces as contacts of the leaves' local faces (hexahedron_faces order): a coarse
/// leaf's face touches the faces of up to four finer ones.
std::vector<CellFaceContact> forest_face_contacts(const std::vector<ForestFace>& faces);

/// The boundary of forest_mesh's mesh: boundary_surface's faces without a leaf on their
/// other side — a coarse face and the finer faces on it, which boundary_surface cannot
/// match, are interior. Vertices no kept triangle uses are dropped.
BoundarySurface forest_boundary_surface(const HexahedralForest& forest, const VolumeMesh& mesh);

}  // namespace altfem
