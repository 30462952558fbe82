#include "shared/quadrature/polyhedron_kernel_point.hpp"

#include <ClpSimplex.hpp>
#include <vector>

#include "shared/geometry/polygon_moments.hpp"

namespace altfem {

std::optional<Eigen::Vector3d> polyhedron_kernel_point(const Polyhedron& polyhedron) {
  // Variables (x, y, z, r): maximise r subject to n_f · x + r ≤ n_f · p_f for each face f
  // (unit outward normal n_f, p_f a vertex of f), 0 ≤ r ≤ size.
  const double size = (polyhedron.vertices.colwise().maxCoeff() - polyhedron.vertices.colwise().minCoeff()).norm();
  const int rows = static_cast<int>(polyhedron.faces.size()), columns = 4;
  std::vector<CoinBigIndex> starts(columns + 1);
  std::vector<int> row_indices(static_cast<std::size_t>(rows) * columns);
  std::vector<double> values(static_cast<std::size_t>(rows) * columns), upper_rows(rows);
  for (int f = 0; f < rows; ++f) {
    const auto& face = polyhedron.faces[f];
    Eigen::MatrixXd polygon(static_cast<Eigen::Index>(face.size()), 3);
    for (size_t k = 0; k < face.size(); ++k)
      polygon.row(static_cast<Eigen::Index>(k)) = polyhedron.vertices.row(face[k]);
    const Eigen::Vector3d normal = polygon_area_vector(polygon).normalized();
    // The plane through the face's mean point: the least-squares plane of a slightly warped face.
    upper_rows[f] = normal.dot(polygon.colwise().mean().transpose());
    for (int j = 0; j < columns; ++j) {
      row_indices[static_cast<std::size_t>(j) * rows + f] = f;
      values[static_cast<std::size_t>(j) * rows + f] = j < 3 ? normal[j] : 1.0;
    }
  }
  for (int j = 0; j <= columns; ++j) starts[j] = static_cast<CoinBigIndex>(j) * rows;
  const std::vector<double> lower_columns{-COIN_DBL_MAX, -COIN_DBL_MAX, -COIN_DBL_MAX, 0.0},
      upper_columns{COIN_DBL_MAX, COIN_DBL_MAX, COIN_DBL_MAX, size}, objective{0.0, 0.0, 0.0, -1.0},
      lower_rows(rows, -COIN_DBL_MAX);
  ClpSimplex simplex;
  simplex.setLogLevel(0);
  simplex.loadProblem(columns, rows, starts.data(), row_indices.data(), values.data(), lower_columns.data(),
                      upper_columns.data(), objective.data(), lower_rows.data(), upper_rows.data());
  // initialSolve: primal() alone reported r = 0 optimal at the origin on a long L-prism.
  simplex.initialSolve();
  if (!simplex.isProvenOptimal()) return std::nullopt;
  const double* solution = simplex.primalColumnSolution();
  if (solution[3] <= 1e-9 * size) return std::nullopt;
  return Eigen::Vector3d(solution[0], solution[1], solution[2]);
}

}  // namespace altfem
