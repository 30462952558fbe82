#include "polyhedral/element_harmonic_basis.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

#include "polyhedral/face_harmonic_coordinates.hpp"
#include "polyhedral/mfs_least_squares.hpp"
#include "shared/geometry/polygon_moments.hpp"
#include "shared/quadrature/polyhedron_rule.hpp"

namespace altfem::harmonic {

namespace {

Eigen::MatrixXd face_polygon(const Polyhedron& polyhedron, const std::vector<int>& face) {
  Eigen::MatrixXd polygon(static_cast<Eigen::Index>(face.size()), 3);
  for (size_t k = 0; k < face.size(); ++k) polygon.row(static_cast<Eigen::Index>(k)) = polyhedron.vertices.row(face[k]);
  return polygon;
}

// Points strictly inside a segment of `length` at about `spacing` apart.
int interior_samples(double length, double spacing) {
  return std::max(0, static_cast<int>(std::lround(length / spacing)) - 1);
}

// Boundary points with their outward normal and, when asked for, the boundary data of
// every node there (#nodes values per point, flattened point by point: δ at a vertex,
// linear along an edge, the face's harmonic coordinates inside a face). The kernel
// centres' samples need no data: evaluating the face coordinates there was a third of
// a cut cell's face work.
struct BoundarySamples {
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<double> data;  // #points · #nodes when with_data, else empty
};

// Appends one point's data, zero: its #nodes values.
double* add_data(BoundarySamples& samples, int nodes) {
  samples.data.resize(samples.data.size() + static_cast<size_t>(nodes), 0.0);
  return samples.data.data() + samples.data.size() - nodes;
}

// Nodes; points inside each edge at about `edge_spacing` (as many as its length
// holds: a short edge of a cut cell gets none, its linear data is fitted through its
// nodes); inside each face a grid of `face_spacing`, kept half a spacing away from the
// face's edges.
BoundarySamples sample_boundary(const Polyhedron& polyhedron, std::span<const ElementFace> faces, double edge_spacing,
                                double face_spacing, bool with_data) {
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
    if (with_data) add_data(samples, nodes)[v] = 1;
  }
  for (const auto& [edge, normal] : edge_normals) {
    const int per_edge = interior_samples(
        (polyhedron.vertices.row(edge.first) - polyhedron.vertices.row(edge.second)).norm(), edge_spacing);
    for (int j = 1; j <= per_edge; ++j) {
      const double t = static_cast<double>(j) / (per_edge + 1);
      samples.points.push_back((1 - t) * polyhedron.vertices.row(edge.first).transpose() +
                               t * polyhedron.vertices.row(edge.second).transpose());
      samples.normals.push_back(normal.normalized());
      if (!with_data) continue;
      double* data = add_data(samples, nodes);
      data[edge.first] = 1 - t;
      data[edge.second] = t;
    }
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
    for (double s = low.x() + face_spacing / 2; s < high.x(); s += face_spacing)
      for (double r = low.y() + face_spacing / 2; r < high.y(); r += face_spacing) {
        bool in = false;
        double distance = INFINITY;
        for (Eigen::Index k = 0; k < local.rows(); ++k) {
          const Eigen::Vector2d a = local.row(k), b = local.row((k + 1) % local.rows());
          if ((a.y() > r) != (b.y() > r) && s < a.x() + (r - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) in = !in;
          const Eigen::Vector2d ab = b - a, x(s, r);
          const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
          distance = std::min(distance, (a + t * ab - x).norm());
        }
        if (in && distance >= face_spacing / 2) inside.push_back(origin + s * u + r * v);
      }
    samples.points.insert(samples.points.end(), inside.begin(), inside.end());
    samples.normals.insert(samples.normals.end(), inside.size(), normal);
    if (inside.empty() || !with_data) continue;
    Eigen::MatrixXd points(static_cast<Eigen::Index>(inside.size()), 3);
    for (size_t p = 0; p < inside.size(); ++p) points.row(static_cast<Eigen::Index>(p)) = inside[p].transpose();
    const Eigen::MatrixXd coordinates = faces[f].coordinates->evaluate(points);  // #points × #face nodes
    for (size_t p = 0; p < inside.size(); ++p) {
      double* data = add_data(samples, nodes);
      for (size_t k = 0; k < face.size(); ++k)
        data[faces[f].nodes[k]] += coordinates(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(k));
    }
  }
  return samples;
}

}  // namespace

namespace {

// The element's own face coordinates, fitted on its loops: a temporary that outlives the
// delegated constructor's call.
struct OwnFaces {
  std::vector<FaceHarmonicCoordinates> storage;
  std::vector<ElementFace> faces;
  OwnFaces(const Polyhedron& element, const MfsOptions& options) {
    storage.reserve(element.faces.size());
    for (const auto& face : element.faces) {
      storage.emplace_back(face_polygon(element, face), options);
      faces.push_back({&storage.back(), face});
    }
  }
};

// The MFS sampling of one spacing (eq. (12)-(13)): kernel centres, dropped where they land
// inside the element or closer than half the offset to its boundary (non-convex
// elements), or closer than half a spacing to a centre kept before (a cut cell's nodes
// can be much closer than the spacing; nearly coincident kernels only make the system
// rank-deficient); collocation points m ≈ 3n, the same sampling 3 times denser along
// edges and in area, also by coordinate (x, y, z: m each) so that every distance test and
// kernel column is one vectorised expression over them.
struct MfsSampling {
  BoundarySamples collocation;
  std::array<Eigen::ArrayXd, 3> coordinates;
  std::vector<Eigen::Vector3d> centres;
};

MfsSampling sample_mfs(const Polyhedron& element, std::span<const ElementFace> faces, double spacing, double offset,
                       int collocation_factor) {
  MfsSampling sampling;
  const BoundarySamples samples = sample_boundary(element, faces, spacing, spacing, false);
  sampling.collocation = sample_boundary(element, faces, spacing / collocation_factor,
                                         spacing / std::sqrt(static_cast<double>(collocation_factor)), true);
  const auto m = static_cast<Eigen::Index>(sampling.collocation.points.size());
  for (int d = 0; d < 3; ++d) {
    sampling.coordinates[d].resize(m);
    for (Eigen::Index i = 0; i < m; ++i) sampling.coordinates[d][i] = sampling.collocation.points[i][d];
  }
  const auto& coordinates = sampling.coordinates;
  const auto closest_squared = [&](const Eigen::Vector3d& centre) {
    return ((coordinates[0] - centre.x()).square() + (coordinates[1] - centre.y()).square() +
            (coordinates[2] - centre.z()).square())
        .minCoeff();
  };
  const Eigen::AlignedBox3d bounds(element.vertices.colwise().minCoeff().transpose(),
                                   element.vertices.colwise().maxCoeff().transpose());
  for (size_t s = 0; s < samples.points.size(); ++s) {
    const Eigen::Vector3d centre = samples.points[s] + offset * samples.normals[s];
    if (std::any_of(sampling.centres.begin(), sampling.centres.end(),
                    [&](const Eigen::Vector3d& kept) { return (kept - centre).squaredNorm() < spacing * spacing / 4; }))
      continue;
    if (closest_squared(centre) < offset * offset / 4) continue;
    // Outside the bounding box is outside; only the others need the winding number.
    if (bounds.contains(centre) && std::abs(winding_number(element, centre)) > 0.5) continue;
    sampling.centres.push_back(centre);
  }
  return sampling;
}

}  // namespace

ElementHarmonicBasis::ElementHarmonicBasis(const Polyhedron& element, const MfsOptions& options)
    : ElementHarmonicBasis(element, OwnFaces(element, options).faces, options) {}

ElementHarmonicBasis::ElementHarmonicBasis(const Polyhedron& element, std::span<const ElementFace> faces,
                                           const MfsOptions& options) {
  if (element.faces.empty()) throw std::invalid_argument("ElementHarmonicBasis: the polyhedron has no face");
  if (faces.size() != element.faces.size())
    throw std::invalid_argument("ElementHarmonicBasis: one face coordinate set per face expected");
  const auto nodes = static_cast<int>(element.vertices.rows());
  origin_ = element.vertices.colwise().mean().transpose();
  scale_ = (element.vertices.rowwise() - origin_.transpose()).rowwise().norm().maxCoeff();
  double diameter = 0;
  for (int i = 0; i < nodes; ++i)
    for (int j = i + 1; j < nodes; ++j)
      diameter = std::max(diameter, (element.vertices.row(i) - element.vertices.row(j)).norm());
  // The sample spacing from the element's surface area, not from its edges: a box of
  // side a gets a / (edge_samples + 1), the paper's 3-5 samples per edge (§5), and any
  // element about the same number of face samples, 6 (edge_samples + 1)². A cut cell's
  // many short edges and a finer neighbour's extra nodes add only what their length holds
  // (tying the spacing to the mean edge length gave cut cells of the bunny ~1000 kernels).
  double area = 0;
  for (const auto& face : element.faces) area += polygon_area_vector(face_polygon(element, face)).norm();
  double spacing = std::sqrt(area / 6) / (options.edge_samples + 1);

  boundary_integrals_ = Eigen::MatrixXd::Zero(nodes, 3);
  for (size_t f = 0; f < element.faces.size(); ++f) {
    const Eigen::MatrixXd polygon = face_polygon(element, element.faces[f]);
    const Eigen::Vector3d normal = polygon_area_vector(polygon).normalized();
    const PolyhedronRule rule = polygon_rule(polygon, 6);
    const Eigen::VectorXd integrals = faces[f].coordinates->evaluate(rule.points).transpose() * rule.weights;
    for (size_t k = 0; k < element.faces[f].size(); ++k)  // #face nodes
      boundary_integrals_.row(faces[f].nodes[k]) += integrals[static_cast<Eigen::Index>(k)] * normal.transpose();
  }

  const double offset = options.offset * diameter;
  MfsSampling sampling = sample_mfs(element, faces, spacing, offset, options.collocation_factor);
  // A cut cell of a detailed surface holds facet vertices much closer than the spacing,
  // whose kernels merge: more nodes than kernels, and its n functions span at most
  // #centres + 4 dimensions. Such dependent functions leave combinations of nodal values
  // without energy on the nodes no other cell holds (the sliced tube: 220 nodes against
  // 170 kernels; its cantilever bent 1.8 times as far as beam theory, and at quadrature
  // order 4 its matrix was singular). The spacing shrinks by 3/4 until the kernels
  // outnumber the nodes by a quarter, at most twice: more kernels at the same offset do
  // not resolve hats narrower than it, and a cell of 800 nodes shrunk 4 times took 14 s
  // and lost its partition of unity to 5e-6 (cells with few nodes never shrink).
  for (int shrink = 0; shrink < 2 && 4 * (sampling.centres.size() + 4) < 5 * static_cast<size_t>(nodes); ++shrink) {
    spacing *= 0.75;
    sampling = sample_mfs(element, faces, spacing, offset, options.collocation_factor);
  }
  const BoundarySamples& collocation = sampling.collocation;
  std::array<Eigen::ArrayXd, 3>& collocation_coordinates = sampling.coordinates;
  const std::vector<Eigen::Vector3d>& centres = sampling.centres;
  const auto m = static_cast<Eigen::Index>(collocation.points.size());
  const auto squared_distances = [&](const Eigen::Vector3d& centre) {
    return (collocation_coordinates[0] - centre.x()).square() + (collocation_coordinates[1] - centre.y()).square() +
           (collocation_coordinates[2] - centre.z()).square();
  };
  centres_.resize(static_cast<Eigen::Index>(centres.size()), 3);
  for (size_t j = 0; j < centres.size(); ++j)
    centres_.row(static_cast<Eigen::Index>(j)) = ((centres[j] - origin_) / scale_).transpose();

  const Eigen::Index c = centres_.rows();
  // The m × (c + 4) system and m × #nodes data live side by side in a per-thread buffer
  // that only grows: building bases cell after cell does not return it to the system and
  // fault its pages in again each time. Aligned like Eigen's own matrices, so the products
  // take the same path whatever the buffer's address: the same cell gives the same bits
  // on any thread (what a cached basis is compared with).
  thread_local std::vector<double, Eigen::aligned_allocator<double>> storage;
  storage.resize(std::max(storage.size(), static_cast<size_t>(m * (c + 4 + nodes))));
  Eigen::Map<Eigen::MatrixXd> augmented(storage.data(), m, c + 4 + nodes);  // [system | data]
  auto system = augmented.leftCols(c + 4);
  auto data = augmented.rightCols(nodes);
  for (int d = 0; d < 3; ++d) collocation_coordinates[d] = (collocation_coordinates[d] - origin_[d]) / scale_;
  // Column by column: the system is column-major, so each kernel column is one
  // contiguous vectorised expression (row by row it was a stride-m scatter).
  const auto fill_system = [&] {
    for (Eigen::Index j = 0; j < c; ++j) system.col(j) = squared_distances(centres_.row(j).transpose()).rsqrt();
    for (int d = 0; d < 3; ++d) system.col(c + d) = collocation_coordinates[d];
    system.col(c + 3).setOnes();
    data = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        collocation.data.data(), m, nodes);
  };
  fill_system();
  boundary_residual_ = solve_mfs_least_squares(augmented, c + 4, fill_system, coefficients_);
  restore_linear_precision((element.vertices.rowwise() - origin_.transpose()) / scale_);
  key_contents();
}

void ElementHarmonicBasis::key_contents() {
  // What write() writes, hashed where it lies.
  CacheKeyHasher hasher;
  hasher.matrix(origin_);
  hasher.scalar(scale_);
  hasher.matrix(centres_);
  hasher.matrix(coefficients_);
  hasher.scalar(boundary_residual_);
  hasher.matrix(boundary_integrals_);
  content_key_ = hasher.value();
}

void ElementHarmonicBasis::restore_linear_precision(const Eigen::MatrixX3d& nodes) {
  // The node functions' data sum to 1 and their node-weighted sums to x at every
  // collocation point, which the linear polynomial fits exactly: in exact arithmetic
  // Σ_i N_i = 1 and Σ_i x_i N_i = x, the coefficients' polynomial rows carrying them and
  // the kernel rows summing to zero. The solve's round-off leaves them off by what its
  // kernel weights amplify (1e-10 on a bunny's cut cell). The smallest change of the
  // coefficients that restores them, C ← C − (C M − E)(MᵀM)⁻¹Mᵀ with M = [Y | 1] (the
  // nodes' local coordinates, #nodes × 4) and E the polynomial rows' identity.
  Eigen::MatrixXd basis(nodes.rows(), 4);
  basis << nodes, Eigen::VectorXd::Ones(nodes.rows());
  Eigen::MatrixXd defect = coefficients_ * basis;  // (#centres + 4) × 4
  defect.bottomRows(4) -= Eigen::Matrix4d::Identity();
  const Eigen::Matrix4d gram = basis.transpose() * basis;
  coefficients_ -= defect * gram.ldlt().solve(basis.transpose());
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

void ElementHarmonicBasis::evaluate(const Eigen::Vector3d& point, Eigen::VectorXd& values) const {
  const Eigen::Vector3d x = (point - origin_) / scale_;
  const Eigen::Index c = centres_.rows();
  Eigen::VectorXd kernel(c + 4);  // 1/r, then x, y, z, 1 (the rows of coefficients_)
  for (Eigen::Index j = 0; j < c; ++j) kernel[j] = 1.0 / (x - centres_.row(j).transpose()).norm();
  kernel.segment<3>(c) = x;
  kernel[c + 3] = 1.0;
  values.noalias() = coefficients_.transpose() * kernel;
}

void ElementHarmonicBasis::evaluate(const Eigen::MatrixXd& points, Eigen::MatrixXd& values,
                                    Eigen::MatrixXd& gradients) const {
  const Eigen::Index count = points.rows(), c = centres_.rows(), n = coefficients_.cols();
  // kernels (#points × (#centres + 4)): 1/r, then the linear polynomial x, y, z, 1;
  // derivatives[d] (#points × #centres): ∂(1/r)/∂x_d = −(x_d − k_d)/r³, local coordinates.
  Eigen::MatrixXd kernels(count, c + 4);
  std::array<Eigen::MatrixXd, 3> derivatives;
  for (auto& derivative : derivatives) derivative.resize(count, c);
  const Eigen::MatrixX3d local = (points.rowwise() - origin_.transpose()) / scale_;
  for (Eigen::Index j = 0; j < c; ++j)
    for (Eigen::Index p = 0; p < count; ++p) {
      const Eigen::RowVector3d offset = local.row(p) - centres_.row(j);
      const double inverse = 1.0 / offset.norm();
      kernels(p, j) = inverse;
      for (int d = 0; d < 3; ++d) derivatives[d](p, j) = -offset[d] * inverse * inverse * inverse;
    }
  kernels.middleCols(c, 3) = local;
  kernels.col(c + 3).setOnes();
  values.noalias() = kernels * coefficients_;
  gradients.resize(count * n, 3);
  Eigen::MatrixXd component(count, n);
  for (int d = 0; d < 3; ++d) {
    component.noalias() = derivatives[d] * coefficients_.topRows(c);
    component.rowwise() += coefficients_.row(c + d);
    // d/dx = (1/scale) d/dx_local; point-major rows.
    for (Eigen::Index p = 0; p < count; ++p) gradients.col(d).segment(p * n, n) = component.row(p).transpose() / scale_;
  }
}

Eigen::MatrixXd ElementHarmonicBasis::values(const Eigen::MatrixXd& points) const {
  Eigen::MatrixXd result, gradients;
  evaluate(points, result, gradients);
  return result;
}

Eigen::MatrixXd ElementHarmonicBasis::centres() const { return (centres_ * scale_).rowwise() + origin_.transpose(); }

ElementHarmonicBasis ElementHarmonicBasis::reordered(const std::vector<int>& order) const {
  ElementHarmonicBasis result = *this;
  // A rebuild hands most remembered cells their own order: same basis, same key.
  bool identity = true;
  for (size_t i = 0; i < order.size() && identity; ++i) identity = order[i] == static_cast<int>(i);
  if (identity) return result;
  result.coefficients_ = coefficients_(Eigen::all, order);
  result.boundary_integrals_ = boundary_integrals_(order, Eigen::all);
  result.key_contents();
  return result;
}

ElementHarmonicBasis ElementHarmonicBasis::moved(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                                 double factor) const {
  ElementHarmonicBasis result = *this;
  // Centres and coefficients are in the local coordinates (x − origin) / scale.
  result.origin_ = to + factor * (origin_ - from);
  result.scale_ = factor * scale_;
  if (factor != 1) result.boundary_integrals_ *= factor * factor;
  result.key_contents();
  return result;
}

void ElementHarmonicBasis::write(BinaryWriter& out) const {
  out.matrix(origin_);
  out.put<double>(scale_);
  out.matrix(centres_);
  out.matrix(coefficients_);
  out.put<double>(boundary_residual_);
  out.matrix(boundary_integrals_);
}

std::optional<ElementHarmonicBasis> ElementHarmonicBasis::read(BinaryReader& in) {
  ElementHarmonicBasis basis;
  if (!in.matrix(basis.origin_)) return std::nullopt;
  const auto scale = in.get<double>();
  if (!scale || !in.matrix(basis.centres_) || !in.matrix(basis.coefficients_)) return std::nullopt;
  const auto residual = in.get<double>();
  if (!residual || !in.matrix(basis.boundary_integrals_)) return std::nullopt;
  basis.scale_ = *scale;
  basis.boundary_residual_ = *residual;
  const auto nodes = basis.coefficients_.cols();
  if (basis.coefficients_.rows() != basis.centres_.rows() + 4 || basis.boundary_integrals_.rows() != nodes ||
      basis.boundary_integrals_.cols() != 3)
    return std::nullopt;
  basis.key_contents();
  return basis;
}

}  // namespace altfem::harmonic
