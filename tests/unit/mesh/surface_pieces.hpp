#pragma once
// A cut surface's pieces and the checks every cut_surface test makes of them.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

#include "shared/mesh/mesh_components.hpp"
#include "shared/mesh/surface_mesh.hpp"

namespace altfem::test {

// The surface's pieces, each as the triangles of one piece (surface_vertex_pieces).
inline std::vector<SurfaceMesh> pieces_of(const SurfaceMesh& surface) {
  const std::vector<int> piece_of = surface_vertex_pieces(surface);
  std::map<int, std::vector<Eigen::Index>> triangles_of;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t)
    triangles_of[piece_of[surface.triangles(t, 0)]].push_back(t);
  std::vector<SurfaceMesh> pieces;
  for (const auto& [piece, triangles] : triangles_of) {
    SurfaceMesh shell;
    shell.vertices = surface.vertices;
    shell.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
    for (std::size_t t = 0; t < triangles.size(); ++t)
      shell.triangles.row(static_cast<Eigen::Index>(t)) = surface.triangles.row(triangles[t]);
    pieces.push_back(shell);
  }
  return pieces;
}

// Every edge is used once in each direction: closed, consistently oriented.
inline bool closed_and_oriented(const SurfaceMesh& surface) {
  std::map<std::pair<int, int>, int> uses;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) ++uses[{surface.triangles(t, k), surface.triangles(t, (k + 1) % 3)}];
  for (const auto& [edge, count] : uses)
    if (count != 1 || uses.count({edge.second, edge.first}) == 0) return false;
  return true;
}

// The volumes of the surface's pieces, smallest first, each checked closed and consistently oriented.
inline std::vector<double> closed_piece_volumes(const SurfaceMesh& surface) {
  std::vector<double> volumes;
  for (const SurfaceMesh& piece : pieces_of(surface)) {
    EXPECT_TRUE(closed_and_oriented(piece));
    volumes.push_back(surface_volume(piece));
  }
  std::sort(volumes.begin(), volumes.end());
  return volumes;
}

// The summed volume of the surface's pieces, each checked closed, and their count.
inline double volume_of_closed_pieces(const SurfaceMesh& surface, std::size_t count) {
  const std::vector<SurfaceMesh> pieces = pieces_of(surface);
  EXPECT_EQ(pieces.size(), count);
  double total = 0;
  for (const SurfaceMesh& piece : pieces) {
    EXPECT_TRUE(closed_and_oriented(piece));
    total += surface_volume(piece);
  }
  return total;
}

// The area of the surface's triangles that lie in the plane x = `x` (or, with `axis`, the
// plane where that coordinate is `x`).
inline double area_in_plane(const SurfaceMesh& surface, double x, int axis = 0) {
  double area = 0;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    const Eigen::Vector3d a = surface.vertices.row(surface.triangles(t, 0)),
                          b = surface.vertices.row(surface.triangles(t, 1)),
                          c = surface.vertices.row(surface.triangles(t, 2));
    if (std::abs(a(axis) - x) < 1e-15 && std::abs(b(axis) - x) < 1e-15 && std::abs(c(axis) - x) < 1e-15)
      area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

}  // namespace altfem::test
