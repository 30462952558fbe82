#pragma once
// Closed loops traced through directed edges in a plane, and the pieces of a planar
// polygon on either side of a cutting plane: what cutting a non-convex cell needs, where a
// face may fall into several pieces on one side and a cell's section into several
// polygons (Kaufmann et al. 2009 §9.4 keep non-convex pieces).
#include <Eigen/Core>
#include <utility>
#include <vector>

namespace altfem {

/// Newell's area vector ½ Σ p_k × p_{k+1} of the loop of node indices `loop` into
/// `positions`: its area times the normal it turns counter-clockwise about.
Eigen::Vector3d loop_area_vector(const std::vector<int>& loop, const std::vector<Eigen::Vector3d>& positions);

/// The closed loops that `edges` (directed node pairs, each used once) form, each counter-
/// clockwise about `normal`. Where several edges leave a node, a loop arriving there turns
/// left as far as it can: the loop keeps the region on its left and two loops that touch
/// at a node stay two. Throws NumericalError when the edges do not close into loops.
/// `positions`: per node index used, its point.
std::vector<std::vector<int>> trace_planar_loops(const std::vector<std::pair<int, int>>& edges,
                                                 const std::vector<Eigen::Vector3d>& positions,
                                                 const Eigen::Vector3d& normal);

struct PolygonPiece {
  std::vector<int> loop;  ///< in the polygon's own orientation
  int side = 0;           ///< +1 or −1: the side of the plane it lies on
};

/// The pieces of the simple planar polygon `loop` on each side of a plane with normal
/// `plane_normal`. `side` gives per node −1, 0, +1, decided exactly by the caller; no edge
/// of `loop` may join nodes on strictly opposite sides (its crossing node is inserted
/// first). Nodes on the plane lie on the line where it meets the polygon's plane: the
/// stretches of that line inside the polygon (between consecutive nodes on it, tested at
/// their midpoints) become edges of the pieces on both sides, and edges of `loop` in the
/// plane go to the side the polygon lies on. Throws NumericalError when the pieces do not
/// close (a polygon that is not simple, or nodes on the line too close to order).
std::vector<PolygonPiece> split_polygon_by_plane(const std::vector<int>& loop,
                                                 const std::vector<Eigen::Vector3d>& positions,
                                                 const std::vector<int>& side, const Eigen::Vector3d& plane_normal);

}  // namespace altfem
