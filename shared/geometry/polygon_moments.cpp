#include "shared/geometry/polygon_moments.hpp"

#include <Eigen/Geometry>
#include <stdexcept>
#include <string>

#include "shared/geometry/homogeneous_integration.hpp"
#include "shared/geometry/monomial_index.hpp"
#include "shared/geometry/monomial_shift.hpp"

namespace altfem {
namespace {

void require_polygon(const Eigen::MatrixXd& polygon, int dimension, int degree) {
  if (polygon.cols() != dimension) {
    throw std::invalid_argument("polygon: expected #vertices × " + std::to_string(dimension) + " coordinates, got " +
                                std::to_string(polygon.cols()) + " columns");
  }
  if (polygon.rows() < 3) {
    throw std::invalid_argument("polygon: expected >= 3 vertices, got " + std::to_string(polygon.rows()));
  }
  if (degree < 0) throw std::invalid_argument("polygon moments: expected degree >= 0, got " + std::to_string(degree));
}

}  // namespace

Eigen::Vector3d polygon_area_vector(const Eigen::MatrixXd& polygon) {
  Eigen::Vector3d twice_area = Eigen::Vector3d::Zero();
  const Eigen::Index count = polygon.rows();
  for (Eigen::Index i = 0; i < count; ++i) {
    const Eigen::Vector3d a = polygon.row(i).transpose();
    const Eigen::Vector3d b = polygon.row((i + 1) % count).transpose();
    twice_area += a.cross(b);
  }
  return 0.5 * twice_area;
}

Eigen::VectorXd polygon_moments_2d(const Eigen::MatrixXd& polygon, int degree) {
  return polygon_moments_2d(polygon, degree, Eigen::Vector2d::Zero(), 1.0);
}

// Lasserre's formula in the plane (Chin, Lasserre & Sukumar 2015): for f homogeneous of
// degree q, ∫_P f dA = 1/(2+q) Σ_edges b_e ∫_e f ds with b_e the signed distance of edge e's
// line from the origin; b_e |e| = v_i × v_{i+1} (2D cross product), so only edge means are
// needed. The origin is the centre of the polygon's MomentFrame, where every b_e is O(1).
Eigen::VectorXd polygon_moments_2d(const Eigen::MatrixXd& polygon, int degree, const Eigen::Vector2d& centre,
                                   double scale) {
  require_polygon(polygon, 2, degree);
  const MomentFrame frame = bounding_box_frame(polygon);
  const Eigen::MatrixXd local = local_coordinates(frame, polygon);
  const Eigen::Matrix<int, Eigen::Dynamic, 2> exponents = monomial_exponents_2d(degree);
  Eigen::VectorXd boundary = Eigen::VectorXd::Zero(exponents.rows());
  for (Eigen::Index i = 0; i < local.rows(); ++i) {
    const Eigen::Vector2d a = local.row(i).transpose();
    const Eigen::Vector2d b = local.row((i + 1) % local.rows()).transpose();
    const double weight = a.x() * b.y() - a.y() * b.x();
    if (weight != 0.0) boundary += weight * segment_moments_2d(a, b, degree);
  }
  Eigen::VectorXd moments(exponents.rows());
  for (Eigen::Index row = 0; row < exponents.rows(); ++row) {
    moments(row) = boundary(row) / (2 + exponents.row(row).sum());
  }
  return moments_about(frame.scale * frame.scale * moments, degree, frame, centre, scale);
}

Eigen::VectorXd planar_polygon_moments(const Eigen::MatrixXd& polygon, int degree) {
  return planar_polygon_moments(polygon, degree, Eigen::Vector3d::Zero(), 1.0);
}

Eigen::VectorXd planar_polygon_moments(const Eigen::MatrixXd& polygon, int degree, const Eigen::Vector3d& centre,
                                       double scale) {
  require_polygon(polygon, 3, degree);
  const MomentFrame frame = bounding_box_frame(polygon);
  const Eigen::MatrixXd local = local_coordinates(frame, polygon);
  const Eigen::Vector3d area_vector = polygon_area_vector(local);
  const double area = area_vector.norm();
  const Eigen::VectorXd moments = area == 0.0 ? Eigen::VectorXd::Zero(monomial_count(degree)).eval()
                                              : planar_face_moments(local, area_vector / area, degree);
  return moments_about(frame.scale * frame.scale * moments, degree, frame, centre, scale);
}

}  // namespace altfem
