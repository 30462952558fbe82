#pragma once
// Polyhedra the unit tests of the polyhedral numerics share (faces counter-clockwise
// seen from outside, as shared/geometry/polyhedron.hpp asks).
#include <Eigen/Core>
#include <vector>

#include "shared/geometry/polyhedron.hpp"

namespace altfem::test {

/// The axis-aligned box [low, high]; vertex v has the corner bits x = 1, y = 2, z = 4.
inline Polyhedron box(const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  Polyhedron result;
  result.vertices.resize(8, 3);
  for (int v = 0; v < 8; ++v)
    result.vertices.row(v) << (v & 1 ? high.x() : low.x()), ((v >> 1) & 1 ? high.y() : low.y()),
        ((v >> 2) & 1 ? high.z() : low.z());
  result.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return result;
}

/// A prism of `height` over a counter-clockwise outline in the plane z = 0, shifted by
/// `offset`: vertices 0..n−1 at the bottom, n..2n−1 on top; faces bottom, top, sides.
inline Polyhedron prism(const std::vector<Eigen::Vector2d>& outline, double height,
                        const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  const int n = static_cast<int>(outline.size());
  Polyhedron result;
  result.vertices.resize(2 * n, 3);
  std::vector<int> bottom, top;
  for (int k = 0; k < n; ++k) {
    result.vertices.row(k) = (Eigen::Vector3d(outline[k].x(), outline[k].y(), 0) + offset).transpose();
    result.vertices.row(k + n) = (Eigen::Vector3d(outline[k].x(), outline[k].y(), height) + offset).transpose();
    bottom.insert(bottom.begin(), k);
    top.push_back(k + n);
  }
  result.faces = {bottom, top};
  for (int k = 0; k < n; ++k) result.faces.push_back({k, (k + 1) % n, (k + 1) % n + n, k + n});
  return result;
}

/// The L-shaped prism over [0,2]×[0,1] ∪ [0,1]×[0,2], height 0.7 (volume 2.1): non-convex,
/// with non-convex hexagonal top and bottom, star-shaped about its centroid.
inline Polyhedron l_prism(const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  return prism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 0.7, offset);
}

}  // namespace altfem::test
