#pragma once
#include <Eigen/Core>
#include <memory>
#include <utility>

#include "shared/mesh/surface_mesh.hpp"

namespace altfem {

/// Closest points on a triangle surface (CGAL AABB tree, built once).
class SurfaceProjection {
public:
  explicit SurfaceProjection(const SurfaceMesh& surface);
  ~SurfaceProjection();
  Eigen::Vector3d closest_point(const Eigen::Vector3d& x) const;
  /// The closest point and the row of `surface.triangles` it lies on.
  std::pair<Eigen::Vector3d, Eigen::Index> closest_point_and_triangle(const Eigen::Vector3d& x) const;

private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace altfem
