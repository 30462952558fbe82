#pragma once
// Seeded planes of every degenerate kind for the cut tests: through nodes with axis,
// diagonal and random normals, nearly parallel to faces, grazing a node, and anywhere
// in the unit cube; and finite blades in them. `count` blades, or ALTFEM_CUT_PLANES of
// them when it is set (docs/verification.md gives the full count's run).
#include <Eigen/Core>
#include <cstdlib>
#include <random>
#include <vector>

#include "shared/mesh/cutting_plane.hpp"

namespace altfem {

inline std::vector<CuttingPlane> seeded_cut_planes(const Eigen::MatrixXd& nodes, int count) {
  std::mt19937_64 random(20261127);
  std::uniform_real_distribution<double> unit(0.0, 1.0), symmetric(-1.0, 1.0);
  const auto random_vector = [&] { return Eigen::Vector3d(symmetric(random), symmetric(random), symmetric(random)); };
  if (const char* requested = std::getenv("ALTFEM_CUT_PLANES")) count = std::atoi(requested);
  std::vector<CuttingPlane> planes;
  for (int trial = 0; trial < count; ++trial) {
    const Eigen::Vector3d node = nodes.row(static_cast<Eigen::Index>(unit(random) * (nodes.rows() - 1)));
    const Eigen::Vector3d axis = Eigen::Vector3d::Unit(trial % 3);
    CuttingPlane plane;
    switch (trial % 5) {
      case 0: plane = {node, axis}; break;
      case 1: plane = {node, Eigen::Vector3d(1, trial % 2 ? 1 : -1, (trial / 2) % 3 - 1)}; break;
      case 2: plane = {node, axis + 1e-9 * random_vector()}; break;
      case 3: plane = {node + 1e-13 * random_vector(), random_vector()}; break;
      default: plane = {Eigen::Vector3d(unit(random), unit(random), unit(random)), random_vector()}; break;
    }
    if (plane.normal.norm() < 1e-3) plane.normal = axis;
    planes.push_back(plane);
  }
  return planes;
}

/// Finite blades in seeded_cut_planes' planes: a square about the plane's point, a
/// triangle with a corner at it, or a long strip whose edge runs through it; half-widths
/// of one or two grid spacings (`spacing`; axis planes give edges along grid lines and
/// corners on nodes) or random.
inline std::vector<CuttingPlane> seeded_cut_polygons(const Eigen::MatrixXd& nodes, double spacing, int count) {
  std::vector<CuttingPlane> blades = seeded_cut_planes(nodes, count);
  std::mt19937_64 random(20261128);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t k = 0; k < blades.size(); ++k) {
    CuttingPlane& blade = blades[k];
    Eigen::Index largest = 0;
    blade.normal.cwiseAbs().maxCoeff(&largest);
    const Eigen::Vector3d first = blade.normal.cross(Eigen::Vector3d::Unit((largest + 1) % 3)).normalized();
    const Eigen::Vector3d second = blade.normal.normalized().cross(first);
    const double width = k % 4 == 3 ? 0.05 + unit(random) : spacing * static_cast<double>(1 + k % 2);
    const Eigen::Vector3d& point = blade.point;
    switch (k % 3) {
      case 0:
        blade.polygon = {point - width * (first + second), point + width * (first - second),
                         point + width * (first + second), point - width * (first - second)};
        break;
      case 1: blade.polygon = {point, point + width * first, point + width * second}; break;
      default:
        blade.polygon = {point - 2 * first, point + 2 * first, point + 2 * first + width * second,
                         point - 2 * first + width * second};
        break;
    }
  }
  return blades;
}

}  // namespace altfem
