#include "shared/mesh/convex_cell.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <tuple>

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
    // The face's plane: that of its largest fan triangle from the first node, not of the
    // first three nodes, which may be (nearly) collinear, as the nodes a split put on an edge are.
    const Eigen::Vector3d a = mesh.nodes.row(loop[0]);
    Eigen::Vector3d b, c, normal = Eigen::Vector3d::Zero();
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
      const Eigen::Vector3d p = mesh.nodes.row(loop[k]), q = mesh.nodes.row(loop[k + 1]);
      const Eigen::Vector3d n = (p - a).cross(q - a);
      if (n.squaredNorm() > normal.squaredNorm()) std::tie(b, c, normal) = std::tuple(p, q, n);
    }
    if (!(normal.squaredNorm() > 0) || collinear(a, b, c)) continue;
    const double allowed = convexity_tolerance * normal.norm() * std::max((b - a).norm(), (c - a).norm());
    for (const int node : cell_nodes)
      if (orientation_sign(a, b, c, mesh.nodes.row(node).transpose()) > 0 &&
          (mesh.nodes.row(node).transpose() - a).dot(normal) > allowed)
        return false;
  }
  return true;
}

std::vector<int> cell_node_set(const PolyhedralMesh& mesh, int cell) {
  std::vector<int> nodes;
  for (const int face : mesh.cell_faces[cell])
    nodes.insert(nodes.end(), mesh.faces[face].begin(), mesh.faces[face].end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace altfem
