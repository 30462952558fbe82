#include "shared/geometry/polyhedron_moments.hpp"

#include <stdexcept>
#include <string>

#include "shared/geometry/homogeneous_integration.hpp"
#include "shared/geometry/monomial_index.hpp"
#include "shared/geometry/monomial_shift.hpp"
#include "shared/geometry/polygon_moments.hpp"

namespace altfem {
namespace {

void require_polyhedron(const Polyhedron& polyhedron, int degree) {
  if (degree < 0)
    throw std::invalid_argument("polyhedron moments: expected degree >= 0, got " + std::to_string(degree));
  if (polyhedron.vertices.cols() != 3) {
    throw std::invalid_argument("polyhedron: expected #vertices × 3 coordinates, got " +
                                std::to_string(polyhedron.vertices.cols()) + " columns");
  }
  if (polyhedron.faces.empty()) throw std::invalid_argument("polyhedron: expected faces, got none");
  const Eigen::Index vertex_count = polyhedron.vertices.rows();
  for (std::size_t f = 0; f < polyhedron.faces.size(); ++f) {
    const std::vector<int>& face = polyhedron.faces[f];
    if (face.size() < 3) {
      throw std::invalid_argument("polyhedron: face " + std::to_string(f) + ": expected >= 3 vertices, got " +
                                  std::to_string(face.size()));
    }
    for (const int index : face) {
      if (index < 0 || index >= vertex_count) {
        throw std::invalid_argument("polyhedron: face " + std::to_string(f) + ": expected vertex indices in [0, " +
                                    std::to_string(vertex_count) + "), got " + std::to_string(index));
      }
    }
  }
}

}  // namespace

Eigen::VectorXd polyhedron_moments(const Polyhedron& polyhedron, int degree) {
  return polyhedron_moments(polyhedron, degree, Eigen::Vector3d::Zero(), 1.0);
}

// Lasserre's formula (Chin, Lasserre & Sukumar 2015): for f homogeneous of degree q,
//   ∫_P f dV = 1/(3+q) Σ_faces (n_F·x_F) ∫_F f dσ,
// n_F the outward unit normal and x_F any point of face F; the face integrals recurse to
// edges (planar_face_moments). The origin is the centre of P's MomentFrame, where every
// n_F·x_F is O(1) and the sum does not cancel.
Eigen::VectorXd polyhedron_moments(const Polyhedron& polyhedron, int degree, const Eigen::Vector3d& centre,
                                   double scale) {
  require_polyhedron(polyhedron, degree);
  const MomentFrame frame = bounding_box_frame(polyhedron.vertices);
  const Eigen::MatrixXd local = local_coordinates(frame, polyhedron.vertices);
  const Eigen::Matrix<int, Eigen::Dynamic, 3> exponents = monomial_exponents(degree);
  Eigen::VectorXd boundary = Eigen::VectorXd::Zero(exponents.rows());
  Eigen::MatrixXd face_vertices;
  for (const std::vector<int>& face : polyhedron.faces) {
    face_vertices.resize(static_cast<Eigen::Index>(face.size()), 3);
    for (std::size_t i = 0; i < face.size(); ++i) face_vertices.row(static_cast<Eigen::Index>(i)) = local.row(face[i]);
    const Eigen::Vector3d area_vector = polygon_area_vector(face_vertices);
    const double area = area_vector.norm();
    if (area == 0.0) continue;
    const Eigen::Vector3d unit_normal = area_vector / area;
    const double distance = unit_normal.dot(face_vertices.row(0).transpose());
    boundary += distance * planar_face_moments(face_vertices, unit_normal, degree);
  }
  Eigen::VectorXd moments(exponents.rows());
  for (Eigen::Index row = 0; row < exponents.rows(); ++row) {
    moments(row) = boundary(row) / (3 + exponents.row(row).sum());
  }
  return moments_about(frame.scale * frame.scale * frame.scale * moments, degree, frame, centre, scale);
}

}  // namespace altfem
