#pragma once
// Seeded planes of every degenerate kind for the cut tests: through nodes with axis,
// diagonal and random normals, nearly parallel to faces, grazing a node, and anywhere
// in the unit cube. `count` planes, or ALTFEM_CUT_PLANES of them when it is set
// (docs/verification.md gives the full count's run).
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

}  // namespace altfem
