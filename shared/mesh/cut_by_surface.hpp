#pragma once
// A cut by a triangulated surface: a cut event's blade read from a surface file (issue
// #33), which may bend, end inside the body (a notch) or run through it. Each triangle T
// of the blade, in turn, is three kinds of planar step of cut_polyhedral_mesh:
//   1. split the cells near T (whose bounding boxes meet T's) by T's plane, the pieces
//      left joined;
//   2. split the cells near each edge of T by the plane through that edge perpendicular
//      to T, so that every face now in T's plane lies inside T or outside it (not at an
//      edge where the blade goes on in T's plane: both sides of it separate);
//   3. separate the faces in T's plane whose centroid T covers.
// So what separates is the blade's triangles themselves, not the sections of whole cells
// a polygon blade covers, and every side decision is the planar cut's exact predicate.
// Where the blade ends inside the body its pieces stay joined around the blade's edge.
// The steps leave a cell near the blade in up to five pieces per triangle that reaches
// it; after each triangle they are joined again, one convex piece a side of its plane or
// the cell whole where it opened nothing between them (join_pieces_by_side), and the
// polyhedral cut at the end joins the pieces of a cell that the blade did not part (one
// non-convex cell per side), never two across a slit where the blade ends inside the
// cell. The cells out of reach of the steps keep their nodes, faces and kind.
#include <Eigen/Core>
#include <array>
#include <utility>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "shared/mesh/join_cut_pieces.hpp"

namespace altfem {

struct SurfaceBlade {
  Eigen::MatrixXd vertices;  ///< #vertices × 3
  /// #triangles × 3; a triangle's positive side is the one its corners turn counter-clockwise seen from
  Eigen::MatrixXi triangles;
};

/// One planar step of a surface blade's cut.
struct SurfaceBladeStep {
  CuttingPlane plane;
  CutScope scope;
  bool triangle_plane = false;             ///< the triangle's own plane (its split or separation), not an edge's
  std::array<Eigen::Vector3d, 3> corners;  ///< the triangle's
  int triangle = 0;                        ///< the blade's triangle whose step this is
  /// the smallest triangle of its flat part: the blade's triangles joined across edges where
  /// it goes on in their plane
  int flat_part = 0;
};

/// The planar steps `blade` is cut by, in order: per triangle up to five (its plane's
/// split, its edges' splits, its separation), a flat part's triangles one after another.
/// Throws std::invalid_argument for a triangle without area.
std::vector<SurfaceBladeStep> surface_blade_steps(const SurfaceBlade& blade);

/// The nodes on one triangle's plane as its steps go: those its split made (a rounding off
/// the plane) and those its edges' splits made between two nodes on it. Its separation
/// takes them on the plane (CutScope::on_plane). One per triangle, made before its split.
class TrianglePlaneNodes {
public:
  /// The scope to cut `step` with (it refers to this object).
  CutScope scope_for(const SurfaceBladeStep& step);
  /// After `step`: the cut's nodes and their sources; nodes from `nodes_before` on are new.
  void after(const SurfaceBladeStep& step, const Eigen::MatrixXd& nodes, const std::vector<NodeSource>& sources,
             Eigen::Index nodes_before);

private:
  std::vector<int> on_plane_;
  std::vector<int> none_;
  std::vector<bool> is_on_plane_;  ///< per node, while the triangle's steps go
};

/// `cut(scope)`, and for a split step that throws NumericalError `cut` again snapping only
/// nodes a few ulps off the plane (CutScope::snap_fraction).
template <typename Cut>
auto cut_snapping_less_if_need_be(const Cut& cut, CutScope scope) {
  if (scope.action != CutAction::split) return cut(scope);
  try {
    return cut(scope);
  } catch (const NumericalError&) {
    scope.snap_fraction = 1e-15;
    return cut(scope);
  }
}

/// Folds a step into the cut so far (PolyhedralCut or TetrahedralCut, `parents` their
/// parent cells or fragments): the step's parents become the cut's input's, its counts
/// add up.
template <typename Cut>
void fold_step_counts(Cut& cut, Cut& step, std::vector<int>& parents, std::vector<int>& step_parents) {
  for (int& parent : step_parents) parent = parents[parent];
  parents = std::move(step_parents);
  cut.separated_faces += step.separated_faces;
  cut.duplicated_nodes += step.duplicated_nodes;
  cut.snapped_nodes += step.snapped_nodes;
}

/// `mesh` cut by every step of `blade`, triangle by triangle on the window of the mesh
/// about each (polyhedral_mesh_window.hpp), and nothing more: the pieces of a cell stay
/// apart, the debris stays (cut_polyhedral_mesh_by_surface clears both). Its parent cells
/// are `mesh`'s, its node sources empty, its counts the steps' summed. `origin` (optional):
/// per node of the result, the node of `mesh` it is or is a copy of, −1 for a node the
/// steps made.
PolyhedralCut cut_by_surface_steps(const PolyhedralMesh& mesh, const SurfaceBlade& blade,
                                   std::vector<int>* origin = nullptr);

/// `cut_by_surface_steps`, then the pieces of a cell the blade did not part joined, the
/// debris cleared and the faces simplified. The result's parent cells are `mesh`'s; its
/// node sources are empty (a node made by a later step lies on an earlier step's face, not
/// on an edge of `mesh`: a field is carried to it by evaluating the field before the cut).
/// The counts add up the steps' (crossed_cells: cells of `mesh` now in several pieces).
PolyhedralCut cut_polyhedral_mesh_by_surface(const PolyhedralMesh& mesh, const SurfaceBlade& blade,
                                             bool compute_geometry);

}  // namespace altfem
