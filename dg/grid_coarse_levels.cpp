#include "dg/grid_coarse_levels.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace altfem::dg {

namespace {

// The trilinear interpolation from the grid of `spacing` with lowest corner `origin` to the
// points (#points × 3): 3 #points × 3 #kept, and the kept nodes' positions (#kept × 3).
struct GridLevel {
  Eigen::SparseMatrix<double> prolongation;
  Eigen::MatrixXd nodes;
};

GridLevel interpolate_from_grid(const Eigen::MatrixXd& points, const Eigen::Vector3d& origin, double spacing) {
  const Eigen::Index point_count = points.rows();
  // Cells per axis: the grid covers every point (the highest ones lie on its last nodes).
  Eigen::Array3i cells;
  for (int a = 0; a < 3; ++a) {
    const double extent = (points.col(a).maxCoeff() - origin[a]) / spacing;
    cells[a] = std::max(1, static_cast<int>(std::ceil(extent - 1e-9)));
  }
  const Eigen::Array3i node_counts = cells + 1;
  const auto node_index = [&](const Eigen::Array3i& n) {
    return n[0] + node_counts[0] * (n[1] + node_counts[1] * n[2]);
  };

  std::vector<Eigen::Triplet<double>> weights;  // (point, grid node, weight)
  weights.reserve(static_cast<size_t>(8 * point_count));
  for (Eigen::Index p = 0; p < point_count; ++p) {
    Eigen::Array3i base;
    Eigen::Array3d local;
    for (int a = 0; a < 3; ++a) {
      const double coordinate = (points(p, a) - origin[a]) / spacing;
      base[a] = std::clamp(static_cast<int>(std::floor(coordinate)), 0, cells[a] - 1);
      local[a] = coordinate - base[a];
      // A point on a grid plane up to round-off (0.3 / 0.1 = 2.9999999999999996) is on it:
      // nested nodes then interpolate from their own node alone.
      if (std::abs(local[a]) < 1e-10) local[a] = 0;
      if (std::abs(local[a] - 1) < 1e-10) local[a] = 1;
    }
    for (int corner = 0; corner < 8; ++corner) {
      double weight = 1;
      Eigen::Array3i node = base;
      for (int a = 0; a < 3; ++a) {
        const bool upper = (corner >> a) & 1;
        weight *= upper ? local[a] : 1 - local[a];
        node[a] += upper;
      }
      if (weight != 0) weights.emplace_back(static_cast<int>(p), node_index(node), weight);
    }
  }
  // Keep the nodes some point uses, numbered in grid order.
  std::vector<int> kept_index(static_cast<size_t>(node_counts.prod()), -1);
  for (const auto& w : weights) kept_index[w.col()] = 0;
  int kept = 0;
  for (int& index : kept_index)
    if (index == 0) index = kept++;
  GridLevel level;
  level.nodes.resize(kept, 3);
  for (int n = 0; n < static_cast<int>(kept_index.size()); ++n)
    if (kept_index[n] >= 0) {
      const Eigen::Array3i grid(n % node_counts[0], (n / node_counts[0]) % node_counts[1],
                                n / (node_counts[0] * node_counts[1]));
      level.nodes.row(kept_index[n]) = (origin.array() + spacing * grid.cast<double>()).transpose();
    }
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(3 * weights.size());
  for (const auto& w : weights)
    for (int i = 0; i < 3; ++i) entries.emplace_back(3 * w.row() + i, 3 * kept_index[w.col()] + i, w.value());
  level.prolongation.resize(3 * point_count, 3 * static_cast<Eigen::Index>(kept));
  level.prolongation.setFromTriplets(entries.begin(), entries.end());
  return level;
}

}  // namespace

std::vector<Eigen::SparseMatrix<double>> grid_coarse_levels(const Eigen::MatrixXd& points, double finest_spacing,
                                                            int coarsest_nodes) {
  if (!(finest_spacing > 0)) throw std::logic_error("grid_coarse_levels: the spacing must be positive");
  std::vector<Eigen::SparseMatrix<double>> prolongations;
  if (points.rows() == 0) return prolongations;
  const Eigen::Vector3d origin = points.colwise().minCoeff().transpose();
  Eigen::MatrixXd level_points = points;
  for (double spacing = finest_spacing; level_points.rows() > coarsest_nodes; spacing *= 2) {
    GridLevel level = interpolate_from_grid(level_points, origin, spacing);
    if (level.nodes.rows() >= level_points.rows()) break;  // no coarser: the points are already this sparse
    prolongations.push_back(std::move(level.prolongation));
    level_points = std::move(level.nodes);
  }
  return prolongations;
}

std::vector<Eigen::SparseMatrix<double>> grid_coarse_levels(const PolyhedralMesh& mesh, const DgLinearSystem& system,
                                                            const VertexCoarseSpace& space) {
  std::vector<double> sizes(static_cast<size_t>(system.cell_count()));
  for (int cell = 0; cell < system.cell_count(); ++cell) sizes[cell] = std::cbrt(system.volume(cell));
  if (sizes.empty()) return {};
  std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
  Eigen::MatrixXd points(static_cast<Eigen::Index>(space.nodes.size()), 3);
  for (size_t v = 0; v < space.nodes.size(); ++v)
    points.row(static_cast<Eigen::Index>(v)) = mesh.nodes.row(space.nodes[v]);
  return grid_coarse_levels(points, 2 * sizes[sizes.size() / 2], coarsest_grid_nodes);
}

}  // namespace altfem::dg
