#pragma once
// The closed blade of the surface-cut tests: a ball of 80 triangles about the unit cube's
// centre, five or six triangles meeting at each vertex, and the volume it encloses.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "shared/mesh/cut_by_surface.hpp"

namespace altfem::test {

// The regular icosahedron about the cube's centre, vertices (0, ±1, ±φ) · scale and their
// cyclic permutations: twelve vertices, four on each grid plane through the centre, five
// triangles meeting at each. Faces outward.
inline SurfaceBlade icosahedron(double scale) {
  const double phi = (1 + std::sqrt(5.0)) / 2;
  SurfaceBlade blade;
  blade.vertices.resize(12, 3);
  int v = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (const double a : {-1.0, 1.0})
      for (const double b : {-phi, phi}) {
        Eigen::Vector3d vertex = Eigen::Vector3d::Zero();
        vertex((axis + 1) % 3) = a;
        vertex((axis + 2) % 3) = b;
        blade.vertices.row(v++) = (Eigen::Vector3d::Constant(0.5) + scale * vertex).transpose();
      }
  // The faces: the triples of vertices pairwise an edge (length 2) apart, turned outward.
  std::vector<std::array<int, 3>> faces;
  const auto edge = [&](int i, int j) {
    return std::abs((blade.vertices.row(i) - blade.vertices.row(j)).norm() - 2 * scale) < 1e-9;
  };
  for (int i = 0; i < 12; ++i)
    for (int j = i + 1; j < 12; ++j)
      for (int k = j + 1; k < 12; ++k)
        if (edge(i, j) && edge(j, k) && edge(i, k)) {
          const Eigen::Vector3d a = blade.vertices.row(i), b = blade.vertices.row(j), c = blade.vertices.row(k);
          const bool outward = (b - a).cross(c - a).dot(a - Eigen::Vector3d::Constant(0.5)) > 0;
          faces.push_back(outward ? std::array<int, 3>{i, j, k} : std::array<int, 3>{i, k, j});
        }
  blade.triangles.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t t = 0; t < faces.size(); ++t)
    blade.triangles.row(static_cast<Eigen::Index>(t)) << faces[t][0], faces[t][1], faces[t][2];
  return blade;
}

// Each triangle of `blade` as four, its edges' midpoints pushed out onto the sphere about
// the cube's centre through its vertices.
inline SurfaceBlade subdivided_on_sphere(const SurfaceBlade& blade) {
  const Eigen::Vector3d centre = Eigen::Vector3d::Constant(0.5);
  const double radius = (Eigen::Vector3d(blade.vertices.row(0)) - centre).norm();
  std::vector<Eigen::Vector3d> vertices;
  for (Eigen::Index v = 0; v < blade.vertices.rows(); ++v) vertices.push_back(blade.vertices.row(v));
  std::map<std::pair<int, int>, int> midpoint;
  const auto middle = [&](int a, int b) {
    const auto [slot, inserted] = midpoint.try_emplace({std::min(a, b), std::max(a, b)}, int(vertices.size()));
    if (inserted) vertices.push_back(centre + radius * (0.5 * (vertices[a] + vertices[b]) - centre).normalized());
    return slot->second;
  };
  SurfaceBlade result;
  result.triangles.resize(4 * blade.triangles.rows(), 3);
  for (Eigen::Index t = 0; t < blade.triangles.rows(); ++t) {
    const int a = blade.triangles(t, 0), b = blade.triangles(t, 1), c = blade.triangles(t, 2);
    const int ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
    result.triangles.row(4 * t) << a, ab, ca;
    result.triangles.row(4 * t + 1) << ab, b, bc;
    result.triangles.row(4 * t + 2) << ca, bc, c;
    result.triangles.row(4 * t + 3) << ab, bc, ca;
  }
  result.vertices.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (std::size_t v = 0; v < vertices.size(); ++v) result.vertices.row(static_cast<Eigen::Index>(v)) = vertices[v];
  return result;
}

// The volume a closed blade encloses (divergence theorem; its triangles face outward).
inline double enclosed_volume(const SurfaceBlade& blade) {
  double volume = 0;
  for (Eigen::Index t = 0; t < blade.triangles.rows(); ++t) {
    const Eigen::Vector3d a = blade.vertices.row(blade.triangles(t, 0)), b = blade.vertices.row(blade.triangles(t, 1)),
                          c = blade.vertices.row(blade.triangles(t, 2));
    volume += a.dot(b.cross(c)) / 6;
  }
  return volume;
}

// A ball of 80 triangles, radius 0.3 about the cube's centre (the icosahedron's vertices
// on the grid planes through it, five or six triangles meeting at each vertex).
inline SurfaceBlade ball_blade() {
  return subdivided_on_sphere(icosahedron(0.3 / std::sqrt(1 + std::pow((1 + std::sqrt(5.0)) / 2, 2))));
}

}  // namespace altfem::test
