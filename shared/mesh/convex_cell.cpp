#include "shared/mesh/convex_cell.hpp"

#include <Eigen/Geometry>
#include <algorithm>

#include "shared/geometry/exact_orientation.hpp"

namespace altfem {
namespace {

// A piece of an earlier cut has rounded nodes, so its faces are planar only to round-off:
// a node counts as behind a face up to this fraction of the face's size.
constexpr double convexity_tolerance = 1e-10;

}  // namespace

bool is_convex_cell(const PolyhedralMesh& mesh, int cell, const std::vector<int>& cell_nodes) {
  for (const int face : mesh.cell_faces[cell]) {
    std::vector<int> loop = mesh.faces[face];
    if (mesh.face_cells(face, 0) != cell) std::reverse(loop.begin(), loop.end());
    const Eigen::Vector3d a = mesh.nodes.row(loop[0]);
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
      const Eigen::Vector3d b = mesh.nodes.row(loop[k]), c = mesh.nodes.row(loop[k + 1]);
      if (collinear(a, b, c)) continue;
      const Eigen::Vector3d normal = (b - a).cross(c - a);
      const double allowed = convexity_tolerance * normal.norm() * std::max((b - a).norm(), (c - a).norm());
      for (const int node : cell_nodes)
        if (orientation_sign(a, b, c, mesh.nodes.row(node).transpose()) > 0 &&
            (mesh.nodes.row(node).transpose() - a).dot(normal) > allowed)
          return false;
      break;
    }
  }
  return true;
}

}  // namespace altfem
