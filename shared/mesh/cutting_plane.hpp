#pragma once
// A planar blade: what a scene's `cut` event holds and what the meshes are cut by.
#include <Eigen/Core>

namespace altfem {

/// The plane through `point` with normal `normal` (not necessarily unit, non-zero). Its
/// positive side is where `normal` points.
struct CuttingPlane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

}  // namespace altfem
