#pragma once
// Hexahedral slicing, part 2: the part of one grid face inside the object, as polygon
// loops built from the surface's crossing of that face. A cut cell's surface pieces leave
// open edges on the cell's faces (where the grid planes cut the surface); on each face
// they are chained, reversed, and closed along the face's perimeter, turning counter-
// clockwise (seen from outside the cell) from where one chain ends to where the next
// starts — the material lies to the left of every boundary piece. Computed once per grid
// face, so both cells see the same polygons with the same nodes.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace altfem {

/// One grid face seen from outside one of its cells.
struct GridFaceView {
  int axis = 0;                ///< the face lies in the plane x_axis = const
  std::array<int, 4> corners;  ///< corner nodes, counter-clockwise seen from outside the cell
  std::string name;            ///< for error messages, e.g. "grid face x 3 (2, 5)"
};

struct GridFaceRegion {
  /// Node loops, counter-clockwise seen from outside the cell; empty with `undetermined`
  /// when the surface does not cross the face (the face is then wholly inside or outside).
  std::vector<std::vector<int>> loops;
  /// Clockwise loops inside `loops`: where the surface pierces the face without reaching
  /// its edges (split_holes makes the region simple polygons).
  std::vector<std::vector<int>> holes;
  bool undetermined = false;
};

/// The region from `segments` (#segments pairs {from, to} of node indices into `points`:
/// the cell's open surface edges on this face, reversed). Throws NumericalError naming the
/// face when the segments do not form chains ending on the perimeter.
GridFaceRegion grid_face_region(const GridFaceView& face, const std::vector<std::array<int, 2>>& segments,
                                const std::vector<Eigen::Vector3d>& points);

}  // namespace altfem
