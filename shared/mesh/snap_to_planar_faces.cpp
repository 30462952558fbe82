#include "shared/mesh/snap_to_planar_faces.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <optional>

#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/corner_tetrahedra.hpp"

namespace altfem {
namespace {

// The point on `face`'s plane nearest x, when x lies within `tolerance` of the face's
// rectangle (enlarged by it); an axis-aligned plane's coordinate is copied, not computed.
std::optional<Eigen::Vector3d> snapped(const PlanarFace& face, const Eigen::Vector3d& x, double tolerance) {
  const Eigen::Vector3d normal = face.u.cross(face.v).normalized();
  const Eigen::Vector3d offset = x - face.origin;
  const double distance = offset.dot(normal);
  if (!(std::abs(distance) <= tolerance)) return std::nullopt;
  for (const Eigen::Vector3d* side : {&face.u, &face.v}) {
    const double along = offset.dot(*side) / side->norm();
    if (along < -tolerance || along > side->norm() + tolerance) return std::nullopt;
  }
  Eigen::Vector3d result = x - distance * normal;
  for (int axis = 0; axis < 3; ++axis)
    if (normal.cwiseAbs()[axis] == 1.0) result[axis] = face.origin[axis];
  return result;
}

}  // namespace

int snap_to_planar_faces(VolumeMesh& mesh, const std::vector<PlanarFace>& faces, double tolerance) {
  if (faces.empty()) return 0;
  std::vector<std::vector<Eigen::Index>> cells_of(static_cast<size_t>(mesh.nodes.rows()));
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (Eigen::Index corner = 0; corner < 4; ++corner) cells_of[mesh.cells(cell, corner)].push_back(cell);
  int moved = 0;
  for (const int node : boundary_surface(mesh).mesh_nodes) {
    const Eigen::Vector3d x = mesh.nodes.row(node);
    for (const PlanarFace& face : faces) {
      const std::optional<Eigen::Vector3d> target = snapped(face, x, tolerance);
      if (!target || *target == x) continue;
      mesh.nodes.row(node) = target->transpose();
      bool inverted = false;
      for (const Eigen::Index cell : cells_of[node]) {
        const auto corner = [&](int c) { return Eigen::Vector3d(mesh.nodes.row(mesh.cells(cell, c))); };
        inverted = inverted || !(six_signed_volume(corner(0), corner(1), corner(2), corner(3)) > 0);
      }
      if (inverted) {
        mesh.nodes.row(node) = x.transpose();
        continue;
      }
      ++moved;
      break;
    }
  }
  return moved;
}

}  // namespace altfem
