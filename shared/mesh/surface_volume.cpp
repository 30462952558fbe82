#include <Eigen/Geometry>

#include "shared/mesh/surface_mesh.hpp"

namespace altfem {

double surface_volume(const SurfaceMesh& surface) {
  // Divergence theorem with the field x/3: each triangle adds det[a, b, c] / 6.
  double volume = 0;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    const Eigen::Vector3d a = surface.vertices.row(surface.triangles(t, 0));
    const Eigen::Vector3d b = surface.vertices.row(surface.triangles(t, 1));
    const Eigen::Vector3d c = surface.vertices.row(surface.triangles(t, 2));
    volume += a.dot(b.cross(c));
  }
  return volume / 6;
}

}  // namespace altfem
