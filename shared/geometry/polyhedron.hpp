#pragma once
// A polyhedron as altfem's polyhedral methods see it (DG elements, harmonic elements,
// cut cells): a closed boundary of planar polygonal faces, convex or not.
#include <Eigen/Core>
#include <vector>

namespace altfem {

struct Polyhedron {
  Eigen::MatrixXd vertices;  ///< #vertices × 3
  /// Each face: indices into `vertices`, at least 3, a planar simple polygon (not
  /// necessarily convex), counter-clockwise seen from outside (outward normal by the
  /// right-hand rule). Together the faces close the boundary.
  std::vector<std::vector<int>> faces;
};

}  // namespace altfem
