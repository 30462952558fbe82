#pragma once
// Closed, outward-oriented triangle surfaces the slicing tests and benchmark share.
#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "shared/mesh/surface_mesh.hpp"

namespace altfem::test {

constexpr double pi = 3.14159265358979323846;

/// The axis-aligned box [low, high] as 12 triangles.
inline SurfaceMesh box_surface(const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  SurfaceMesh box;
  box.vertices.resize(8, 3);
  for (int v = 0; v < 8; ++v)
    box.vertices.row(v) << (v & 1 ? high.x() : low.x()), (v & 2 ? high.y() : low.y()), (v & 4 ? high.z() : low.z());
  box.triangles.resize(12, 3);
  box.triangles << 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1,
      7, 5;
  return box;
}

/// A torus about the z axis: a periodic (u, v) grid of `u_count` × `v_count` points.
inline SurfaceMesh torus(double major, double minor, int u_count, int v_count, const Eigen::Vector3d& centre) {
  SurfaceMesh surface;
  surface.vertices.resize(u_count * v_count, 3);
  for (int i = 0; i < u_count; ++i)
    for (int j = 0; j < v_count; ++j) {
      const double u = 2 * pi * i / u_count, v = 2 * pi * j / v_count;
      surface.vertices.row(i * v_count + j) =
          (centre + Eigen::Vector3d((major + minor * std::cos(v)) * std::cos(u),
                                    (major + minor * std::cos(v)) * std::sin(u), minor * std::sin(v)))
              .transpose();
    }
  surface.triangles.resize(2 * u_count * v_count, 3);
  for (int i = 0; i < u_count; ++i)
    for (int j = 0; j < v_count; ++j) {
      const int a = i * v_count + j, b = ((i + 1) % u_count) * v_count + j,
                c = ((i + 1) % u_count) * v_count + (j + 1) % v_count, d = i * v_count + (j + 1) % v_count;
      surface.triangles.row(2 * (i * v_count + j)) << a, b, c;
      surface.triangles.row(2 * (i * v_count + j) + 1) << a, c, d;
    }
  return surface;
}

/// A latitude–longitude sphere: `rings` bands of `segments` quads, fans at the poles.
inline SurfaceMesh sphere(double radius, int rings, int segments, const Eigen::Vector3d& centre) {
  SurfaceMesh surface;
  const int vertex_count = 2 + (rings - 1) * segments;
  surface.vertices.resize(vertex_count, 3);
  surface.vertices.row(0) = (centre - radius * Eigen::Vector3d::UnitZ()).transpose();
  surface.vertices.row(vertex_count - 1) = (centre + radius * Eigen::Vector3d::UnitZ()).transpose();
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double polar = pi * r / rings, azimuth = 2 * pi * s / segments;
      surface.vertices.row(1 + (r - 1) * segments + s) =
          (centre + radius * Eigen::Vector3d(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                                             -std::cos(polar)))
              .transpose();
    }
  std::vector<Eigen::Vector3i> triangles;
  auto ring_vertex = [&](int r, int s) { return 1 + (r - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) {
    triangles.emplace_back(0, ring_vertex(1, s + 1), ring_vertex(1, s));
    triangles.emplace_back(vertex_count - 1, ring_vertex(rings - 1, s), ring_vertex(rings - 1, s + 1));
    for (int r = 1; r < rings - 1; ++r) {
      triangles.emplace_back(ring_vertex(r, s), ring_vertex(r, s + 1), ring_vertex(r + 1, s + 1));
      triangles.emplace_back(ring_vertex(r, s), ring_vertex(r + 1, s + 1), ring_vertex(r + 1, s));
    }
  }
  surface.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t) surface.triangles.row(t) = triangles[t].transpose();
  return surface;
}

/// The prism of the polygon `profile` (points (x, z), counter-clockwise) from y = 0 to
/// y = `length`, its end faces the triangles `fan` of the profile (indices into it).
inline SurfaceMesh prism(const std::vector<Eigen::Vector2d>& profile, const std::vector<Eigen::Vector3i>& fan,
                         double length) {
  const int n = static_cast<int>(profile.size());
  SurfaceMesh surface;
  surface.vertices.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    surface.vertices.row(i) << profile[i].x(), 0, profile[i].y();
    surface.vertices.row(n + i) << profile[i].x(), length, profile[i].y();
  }
  std::vector<Eigen::Vector3i> triangles;
  // Counter-clockwise in (x, z) turns about −y: as given at y = 0, reversed at y = length.
  for (const Eigen::Vector3i& t : fan) {
    triangles.push_back(t);
    triangles.emplace_back(n + t[0], n + t[2], n + t[1]);
  }
  for (int i = 0; i < n; ++i) {
    const int next = (i + 1) % n;
    triangles.emplace_back(i, n + i, n + next);
    triangles.emplace_back(i, n + next, next);
  }
  surface.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t) surface.triangles.row(t) = triangles[t].transpose();
  return surface;
}

}  // namespace altfem::test
