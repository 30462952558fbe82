#pragma once
#include <Eigen/Core>
#include <vector>

#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// Material points embedded in a Lagrange mesh (DESIGN.md "embedding evaluator"):
/// each point is located in a cell and keeps that cell's basis values there, so the
/// displacement of all points is a sparse product. Points inside no cell (Mesh_3's
/// surface only approximates the input; ENVIRONMENT.md) are attached to the cell of
/// the nearest boundary point (CGAL AABB tree) and extrapolated with its inverse
/// map; none is dropped, and the largest distance is reported.
class PointEmbedding {
public:
  /// points: #points × 3.
  PointEmbedding(const VolumeMesh& mesh, const Eigen::MatrixXd& points);

  /// Displacement at every point (#points × 3) from the nodal displacement u (3·#nodes).
  Eigen::MatrixXd displacement(const Eigen::VectorXd& u) const;
  int outside_count() const { return outside_count_; }
  /// The largest distance from an outside point to the mesh boundary (0 if none).
  double max_outside_distance() const { return max_outside_distance_; }

private:
  int nodes_per_cell_ = 0;
  std::vector<int> nodes_;       // #points × nodes-per-cell
  std::vector<double> weights_;  // #points × nodes-per-cell: N_a(ξ_point)
  int outside_count_ = 0;
  double max_outside_distance_ = 0;
};

}  // namespace altfem
