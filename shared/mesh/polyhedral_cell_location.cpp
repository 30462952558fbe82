#include "shared/mesh/polyhedral_cell_location.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/Geometry>

namespace altfem {

namespace {

double distance_to_segment(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - x).norm();
}

// Distance from x to a planar simple polygon (loop of mesh nodes, convex or not): to
// its plane when the projection falls inside (even-odd rule in the plane), else to the
// nearest edge.
double distance_to_polygon(const Eigen::MatrixXd& nodes, const std::vector<int>& loop, const Eigen::Vector3d& normal,
                           const Eigen::Vector3d& x) {
  const auto n = loop.size();
  const Eigen::Vector3d origin = nodes.row(loop[0]).transpose();
  const Eigen::Vector3d u = (nodes.row(loop[1]).transpose() - origin).normalized();
  const Eigen::Vector3d v = normal.cross(u);
  const Eigen::Vector2d p((x - origin).dot(u), (x - origin).dot(v));
  bool inside = false;
  double edge_distance = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d a3 = nodes.row(loop[k]).transpose(), b3 = nodes.row(loop[(k + 1) % n]).transpose();
    const Eigen::Vector2d a((a3 - origin).dot(u), (a3 - origin).dot(v)), b((b3 - origin).dot(u), (b3 - origin).dot(v));
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
    edge_distance = std::min(edge_distance, distance_to_segment(x, a3, b3));
  }
  return inside ? std::abs((x - origin).dot(normal)) : edge_distance;
}

// winding_number of cell_polyhedron(mesh, cell), read from the mesh's faces in place:
// copying a cut cell of thousands of facets for every located point cost more than the
// solid angles themselves. A stored loop is outward for face_cells(f, 0), so the other
// cell sees its solid angle negated.
double cell_winding_number(const PolyhedralMesh& mesh, int cell, const Eigen::Vector3d& x) {
  double total = 0;
  for (int face : mesh.cell_faces[cell])
    total += (mesh.face_cells(face, 0) == cell ? 1.0 : -1.0) * fan_solid_angle(mesh.nodes, mesh.faces[face], x);
  return total / (4 * std::numbers::pi);
}

}  // namespace

double distance_to_cell_boundary(const PolyhedralMesh& mesh, int cell, const Eigen::Vector3d& x) {
  double distance = std::numeric_limits<double>::infinity();
  for (int face : mesh.cell_faces[cell])
    distance = std::min(distance,
                        distance_to_polygon(mesh.nodes, mesh.faces[face], mesh.face_normals.row(face).transpose(), x));
  return distance;
}

bool cell_holds(const PolyhedralMesh& mesh, int cell, const Eigen::Vector3d& x, double tolerance) {
  // Behind every face plane is inside any closed cell (the planes' intersection is its
  // kernel); in front of one is outside a convex cell. Only the rest needs the winding
  // number: a non-convex cell's points outside its kernel.
  double plane_distance = -std::numeric_limits<double>::infinity();
  for (int face : mesh.cell_faces[cell]) {
    const double outward = mesh.face_cells(face, 0) == cell ? 1.0 : -1.0;
    plane_distance = std::max(
        plane_distance,
        outward * (x - mesh.face_centroids.row(face).transpose()).dot(mesh.face_normals.row(face).transpose()));
  }
  if (plane_distance <= tolerance) return true;
  if (convex_kind(mesh.cell_kinds[cell])) return false;
  // A node of the cell (the stitched and MLS embeddings locate every mesh node) lies on its
  // boundary, where the winding number is about ½ and only the distance to the faces
  // decides; comparing with the nodes costs a fraction of either on a cut cell of
  // thousands of facets.
  for (int face : mesh.cell_faces[cell])
    for (int node : mesh.faces[face])
      if ((mesh.nodes.row(node).transpose() - x).squaredNorm() <= tolerance * tolerance) return true;
  return cell_winding_number(mesh, cell, x) > 0.5 || distance_to_cell_boundary(mesh, cell, x) <= tolerance;
}

}  // namespace altfem
