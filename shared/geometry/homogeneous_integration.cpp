#include "shared/geometry/homogeneous_integration.hpp"

#include <Eigen/Geometry>

#include "shared/geometry/monomial_index.hpp"

namespace altfem {
namespace {

// Chin, Lasserre & Sukumar (2015), their facet recursion in one dimension: on the segment from p,
// with f homogeneous of degree q, d/ds[s f] = (1+q) f − p·∇f, so
//   ∫_e f ds = (|e| f(end) + ∫_e p·∇f ds) / (1+q),
// and p·∇x^α = Σ_k p_k α_k x^(α−e_k) reuses the lower-degree means (divide by |e|).
template <int D>
Eigen::VectorXd segment_means(const Eigen::Matrix<double, D, 1>& start, const Eigen::Matrix<double, D, 1>& end,
                              const Eigen::Matrix<int, Eigen::Dynamic, D>& exponents) {
  const Eigen::Index count = exponents.rows();
  Eigen::VectorXd end_power(count);
  Eigen::VectorXd mean(count);
  end_power(0) = 1.0;
  mean(0) = 1.0;
  for (Eigen::Index row = 1; row < count; ++row) {
    const Eigen::Matrix<int, 1, D> alpha = exponents.row(row);
    int first_axis = 0;
    while (alpha(first_axis) == 0) ++first_axis;
    Eigen::Matrix<int, 1, D> lowered = alpha;
    --lowered(first_axis);
    end_power(row) = end(first_axis) * end_power(monomial_index(lowered));
    double sum = end_power(row);
    for (int axis = 0; axis < D; ++axis) {
      if (alpha(axis) == 0) continue;
      lowered = alpha;
      --lowered(axis);
      sum += alpha(axis) * start(axis) * mean(monomial_index(lowered));
    }
    mean(row) = sum / (1 + alpha.sum());
  }
  return mean;
}

}  // namespace

Eigen::VectorXd segment_moments_2d(const Eigen::Vector2d& start, const Eigen::Vector2d& end, int degree) {
  return segment_means<2>(start, end, monomial_exponents_2d(degree));
}

// Chin, Lasserre & Sukumar (2015), their facet recursion on a face F with x0 any point of its plane:
//   ∫_F f dσ = 1/(2+q) [ Σ_edges d_e ∫_e f ds + ∫_F x0·∇f dσ ],
// d_e the signed distance from x0 to edge e's line along the edge's outward in-plane
// normal (t_e × n)/|t_e|. With x0 = vertex 0 the two edges through it have d_e = 0, and
// d_e ∫_e f ds = ((v_i − x0)·(t_e × n)) · mean_e(f) needs no edge length.
Eigen::VectorXd planar_face_moments(const Eigen::MatrixXd& face, const Eigen::Vector3d& unit_normal, int degree) {
  const Eigen::Matrix<int, Eigen::Dynamic, 3> exponents = monomial_exponents(degree);
  const Eigen::Index vertex_count = face.rows();
  const Eigen::Vector3d x0 = face.row(0).transpose();
  Eigen::VectorXd boundary = Eigen::VectorXd::Zero(exponents.rows());
  for (Eigen::Index i = 1; i + 1 < vertex_count; ++i) {
    const Eigen::Vector3d start = face.row(i).transpose();
    const Eigen::Vector3d end = face.row(i + 1).transpose();
    const double weight = (start - x0).dot((end - start).cross(unit_normal));
    if (weight != 0.0) boundary += weight * segment_means<3>(start, end, exponents);
  }
  Eigen::VectorXd moments(exponents.rows());
  for (Eigen::Index row = 0; row < exponents.rows(); ++row) {
    const Eigen::Matrix<int, 1, 3> alpha = exponents.row(row);
    double sum = boundary(row);
    for (int axis = 0; axis < 3; ++axis) {
      if (alpha(axis) == 0) continue;
      Eigen::Matrix<int, 1, 3> lowered = alpha;
      --lowered(axis);
      sum += alpha(axis) * x0(axis) * moments(monomial_index(lowered));
    }
    moments(row) = sum / (2 + alpha.sum());
  }
  return moments;
}

}  // namespace altfem
