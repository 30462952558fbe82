#include "polyhedral/element_harmonic_basis.hpp"

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "polyhedral/face_harmonic_coordinates.hpp"
#include "shared/geometry/polygon_moments.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"

namespace altfem::harmonic {

namespace {

Eigen::MatrixXd face_polygon(const Polyhedron& polyhedron, const std::vector<int>& face) {
  Eigen::MatrixXd polygon(static_cast<Eigen::Index>(face.size()), 3);
  for (size_t k = 0; k < face.size(); ++k) polygon.row(static_cast<Eigen::Index>(k)) = polyhedron.vertices.row(face[k]);
  return polygon;
}

// Boundary points with their outward normal and the boundary data of every node there
// (#nodes values: δ at a vertex, linear along an edge, the face's harmonic coordinates
// inside a face).
struct BoundarySamples {
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<Eigen::VectorXd> data;
};

// Nodes; `per_edge` points inside each edge; inside each face a grid of about the
// edges' spacing, kept half a spacing away from the face's edges.
BoundarySamples sample_boundary(const Polyhedron& polyhedron, const std::vector<FaceHarmonicCoordinates>& faces,
                                int per_edge, double spacing) {
  const auto nodes = static_cast<int>(polyhedron.vertices.rows());
  std::vector<Eigen::Vector3d> face_normals;
  std::vector<Eigen::Vector3d> vertex_normals(nodes, Eigen::Vector3d::Zero());
  std::map<std::pair<int, int>, Eigen::Vector3d> edge_normals;
  for (const auto& face : polyhedron.faces) {
    face_normals.push_back(polygon_area_vector(face_polygon(polyhedron, face)).normalized());
    for (size_t k = 0; k < face.size(); ++k) {
      const int a = face[k], b = face[(k + 1) % face.size()];
      vertex_normals[a] += face_normals.back();
      // try_emplace: a default-constructed Eigen vector is uninitialised.
      edge_normals.try_emplace({std::min(a, b), std::max(a, b)}, Eigen::Vector3d::Zero()).first->second +=
          face_normals.back();
    }
  }
  BoundarySamples samples;
  for (int v = 0; v < nodes; ++v) {
    samples.points.push_back(polyhedron.vertices.row(v).transpose());
    samples.normals.push_back(vertex_normals[v].normalized());
    samples.data.push_back(Eigen::VectorXd::Unit(nodes, v));
  }
  for (const auto& [edge, normal] : edge_normals)
    for (int j = 1; j <= per_edge; ++j) {
      const double t = static_cast<double>(j) / (per_edge + 1);
      samples.points.push_back((1 - t) * polyhedron.vertices.row(edge.first).transpose() +
                               t * polyhedron.vertices.row(edge.second).transpose());
      samples.normals.push_back(normal.normalized());
      Eigen::VectorXd data = Eigen::VectorXd::Zero(nodes);
      data[edge.first] = 1 - t;
      data[edge.second] = t;
      samples.data.push_back(data);
    }
  for (size_t f = 0; f < polyhedron.faces.size(); ++f) {
    const auto& face = polyhedron.faces[f];
    const Eigen::MatrixXd polygon = face_polygon(polyhedron, face);
    // A grid in the face's plane; points inside the polygon (winding about the normal)
    // and at least half a spacing from its edges.
    const Eigen::Vector3d normal = face_normals[f];
    const Eigen::Vector3d u = (polygon.row(1) - polygon.row(0)).normalized().transpose();
    const Eigen::Vector3d v = normal.cross(u);
    const Eigen::Vector3d origin = polygon.row(0).transpose();
    Eigen::MatrixX2d local(polygon.rows(), 2);
    for (Eigen::Index k = 0; k < polygon.rows(); ++k) {
      const Eigen::Vector3d d = polygon.row(k).transpose() - origin;
      local.row(k) << d.dot(u), d.dot(v);
    }
    const Eigen::Vector2d low = local.colwise().minCoeff(), high = local.colwise().maxCoeff();
    std::vector<Eigen::Vector3d> inside;
    for (double s = low.x() + spacing / 2; s < high.x(); s += spacing)
      for (double r = low.y() + spacing / 2; r < high.y(); r += spacing) {
        bool in = false;
        double distance = INFINITY;
        for (Eigen::Index k = 0; k < local.rows(); ++k) {
          const Eigen::Vector2d a = local.row(k), b = local.row((k + 1) % local.rows());
          if ((a.y() > r) != (b.y() > r) && s < a.x() + (r - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) in = !in;
          const Eigen::Vector2d ab = b - a, x(s, r);
          const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
          distance = std::min(distance, (a + t * ab - x).norm());
        }
        if (in && distance >= spacing / 2) inside.push_back(origin + s * u + r * v);
      }
    if (inside.empty()) continue;
    Eigen::MatrixXd points(static_cast<Eigen::Index>(inside.size()), 3);
    for (size_t p = 0; p < inside.size(); ++p) points.row(static_cast<Eigen::Index>(p)) = inside[p].transpose();
    const Eigen::MatrixXd coordinates = faces[f].evaluate(points);  // #points × #face nodes
    for (size_t p = 0; p < inside.size(); ++p) {
      samples.points.push_back(inside[p]);
      samples.normals.push_back(normal);
      Eigen::VectorXd data = Eigen::VectorXd::Zero(nodes);
      for (size_t k = 0; k < face.size(); ++k) data[face[k]] += coordinates(static_cast<Eigen::Index>(p), k);
      samples.data.push_back(data);
    }
  }
  return samples;
}

// The solid angle of triangle (a, b, c) seen from the origin (Van Oosterom & Strackee 1983).
double solid_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2 * std::atan2(numerator, denominator);
}

}  // namespace

double winding_number(const Polyhedron& polyhedron, const Eigen::Vector3d& x) {
  double total = 0;
  for (const auto& face : polyhedron.faces) {
    const Eigen::Vector3d first = polyhedron.vertices.row(face[0]).transpose() - x;
    for (size_t k = 1; k + 1 < face.size(); ++k)
      total += solid_angle(first, polyhedron.vertices.row(face[k]).transpose() - x,
                           polyhedron.vertices.row(face[k + 1]).transpose() - x);
  }
  return total / (4 * std::numbers::pi);
}

ElementHarmonicBasis::ElementHarmonicBasis(const Polyhedron& element, const MfsOptions& options) {
  if (element.faces.empty()) throw std::invalid_argument("ElementHarmonicBasis: the polyhedron has no face");
  const auto nodes = static_cast<int>(element.vertices.rows());
  origin_ = element.vertices.colwise().mean().transpose();
  scale_ = (element.vertices.rowwise() - origin_.transpose()).rowwise().norm().maxCoeff();
  double diameter = 0, edge_length = 0;
  int edges = 0;
  for (int i = 0; i < nodes; ++i)
    for (int j = i + 1; j < nodes; ++j) diameter = std::max(diameter, (element.vertices.row(i) - element.vertices.row(j)).norm());
  for (const auto& face : element.faces)
    for (size_t k = 0; k < face.size(); ++k, ++edges)
      edge_length += (element.vertices.row(face[k]) - element.vertices.row(face[(k + 1) % face.size()])).norm();
  const double spacing = edge_length / edges / (options.edge_samples + 1);

  std::vector<FaceHarmonicCoordinates> faces;
  faces.reserve(element.faces.size());
  for (const auto& face : element.faces) faces.emplace_back(face_polygon(element, face), options);
  boundary_integrals_ = Eigen::MatrixXd::Zero(nodes, 3);
  for (size_t f = 0; f < element.faces.size(); ++f) {
    const Eigen::MatrixXd polygon = face_polygon(element, element.faces[f]);
    const Eigen::Vector3d normal = polygon_area_vector(polygon).normalized();
    const PolyhedronRule rule = polygon_rule(polygon, 6);
    const Eigen::VectorXd integrals = faces[f].evaluate(rule.points).transpose() * rule.weights;  // #face nodes
    for (size_t k = 0; k < element.faces[f].size(); ++k)
      boundary_integrals_.row(element.faces[f][k]) += integrals[static_cast<Eigen::Index>(k)] * normal.transpose();
  }

  // Kernel centres (eq. (12)), dropped where they land inside the element or closer
  // than half the offset to its boundary (non-convex elements).
  const BoundarySamples samples = sample_boundary(element, faces, options.edge_samples, spacing);
  const int dense_per_edge = options.collocation_factor * (options.edge_samples + 1) - 1;
  const BoundarySamples collocation =
      sample_boundary(element, faces, dense_per_edge, spacing / std::sqrt(static_cast<double>(options.collocation_factor)));
  std::vector<Eigen::Vector3d> centres;
  const double offset = options.offset * diameter;
  for (size_t s = 0; s < samples.points.size(); ++s) {
    const Eigen::Vector3d centre = samples.points[s] + offset * samples.normals[s];
    if (std::abs(winding_number(element, centre)) > 0.5) continue;
    bool too_close = false;
    for (const auto& point : collocation.points)
      if ((point - centre).squaredNorm() < 0.25 * offset * offset) {
        too_close = true;
        break;
      }
    if (!too_close) centres.push_back((centre - origin_) / scale_);
  }
  centres_.resize(static_cast<Eigen::Index>(centres.size()), 3);
  for (size_t j = 0; j < centres.size(); ++j) centres_.row(static_cast<Eigen::Index>(j)) = centres[j].transpose();

  const auto m = static_cast<Eigen::Index>(collocation.points.size());
  const Eigen::Index c = centres_.rows();
  // The m × (c + 4) system and m × #nodes data (about 1 MB for a hexahedron) live in
  // per-thread buffers that only grow: building bases cell after cell does not return
  // them to the system and fault their pages in again each time.
  thread_local std::vector<double> system_storage, data_storage;
  system_storage.resize(std::max(system_storage.size(), static_cast<size_t>(m * (c + 4))));
  data_storage.resize(std::max(data_storage.size(), static_cast<size_t>(m * nodes)));
  Eigen::Map<Eigen::MatrixXd> system(system_storage.data(), m, c + 4), data(data_storage.data(), m, nodes);
  // Column by column: the system is column-major, so each kernel column is written
  // contiguously (row by row it was a stride-m scatter, 15% of the basis' time).
  Eigen::Matrix3Xd local(3, m);
  for (Eigen::Index i = 0; i < m; ++i) local.col(i) = (collocation.points[i] - origin_) / scale_;
  const auto fill_system = [&] {
    for (Eigen::Index j = 0; j < c; ++j) {
      const Eigen::Vector3d centre = centres_.row(j).transpose();
      for (Eigen::Index i = 0; i < m; ++i) system(i, j) = 1.0 / (local.col(i) - centre).norm();
    }
    system.middleCols(c, 3) = local.transpose();
    system.col(c + 3).setOnes();
    for (Eigen::Index i = 0; i < m; ++i) data.row(i) = collocation.data[i].transpose();
  };
  fill_system();
  // One factorisation for every node's right-hand side: blocked Householder QR in place
  // (level-3, several times faster than column pivoting). Qᵀ·data gives the coefficients
  // from its top rows and the misfit from the rest. When R's diagonal shows the kernel
  // columns (nearly) dependent, the complete orthogonal decomposition gives the
  // minimum-norm least-squares solution instead (the pseudo-inverse, §5).
  const Eigen::HouseholderQR<Eigen::Ref<Eigen::MatrixXd>> qr(system);
  const auto diagonal = qr.matrixQR().diagonal().cwiseAbs();
  if (diagonal.minCoeff() > 1e-12 * diagonal.maxCoeff()) {
    data.applyOnTheLeft(qr.householderQ().transpose());
    coefficients_ = qr.matrixQR().topRows(c + 4).triangularView<Eigen::Upper>().solve(data.topRows(c + 4));
    boundary_residual_ = std::sqrt(data.bottomRows(m - c - 4).squaredNorm() / static_cast<double>(data.size()));
  } else {
    fill_system();
    coefficients_ = system.completeOrthogonalDecomposition().solve(data);
    boundary_residual_ = std::sqrt((system * coefficients_ - data).squaredNorm() / static_cast<double>(data.size()));
  }
}

void ElementHarmonicBasis::evaluate(const Eigen::Vector3d& point, Eigen::VectorXd& values,
                                    Eigen::MatrixXd& gradients) const {
  const Eigen::Vector3d x = (point - origin_) / scale_;
  const Eigen::Index c = centres_.rows();
  values = coefficients_.row(c) * x.x() + coefficients_.row(c + 1) * x.y() + coefficients_.row(c + 2) * x.z();
  values += coefficients_.row(c + 3).transpose();
  gradients.resize(coefficients_.cols(), 3);
  for (int d = 0; d < 3; ++d) gradients.col(d) = coefficients_.row(c + d).transpose();
  for (Eigen::Index j = 0; j < c; ++j) {
    const Eigen::Vector3d offset = x - centres_.row(j).transpose();
    const double inverse = 1.0 / offset.norm();
    values += inverse * coefficients_.row(j).transpose();
    gradients -= (inverse * inverse * inverse) * coefficients_.row(j).transpose() * offset.transpose();
  }
  gradients /= scale_;  // d/dx = (1/scale) d/dx_local
}

Eigen::MatrixXd ElementHarmonicBasis::values(const Eigen::MatrixXd& points) const {
  Eigen::MatrixXd result(points.rows(), node_count());
  Eigen::VectorXd values;
  Eigen::MatrixXd gradients;
  for (Eigen::Index p = 0; p < points.rows(); ++p) {
    evaluate(points.row(p).transpose(), values, gradients);
    result.row(p) = values.transpose();
  }
  return result;
}

Eigen::MatrixXd ElementHarmonicBasis::centres() const {
  return (centres_ * scale_).rowwise() + origin_.transpose();
}

}  // namespace altfem::harmonic
