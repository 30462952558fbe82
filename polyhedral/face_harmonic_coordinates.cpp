#include "polyhedral/face_harmonic_coordinates.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "polyhedral/mfs_least_squares.hpp"
#include "shared/geometry/polygon_moments.hpp"

namespace altfem::harmonic {

namespace {

// Points along the boundary of a counter-clockwise polygon (#nodes × 2): each node, then
// evenly spaced points inside each edge about `spacing` apart (none on an edge shorter
// than 1.5 spacings: its data is linear between its nodes). For each point: the edge it lies on,
// the parameter t along it (0 at its first node), and the outward unit normal (at a node:
// the mean of its two edges' normals).
struct BoundarySamples {
  Eigen::MatrixX2d points;
  Eigen::MatrixX2d normals;
  std::vector<int> edges;
  std::vector<double> parameters;
};

BoundarySamples sample_boundary(const Eigen::MatrixX2d& polygon, double spacing) {
  const auto n = static_cast<int>(polygon.rows());
  std::vector<Eigen::Vector2d> edge_normals(n);
  std::vector<int> per_edge(n);
  int count = 0;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d along = polygon.row((k + 1) % n) - polygon.row(k);
    edge_normals[k] = Eigen::Vector2d(along.y(), -along.x()).normalized();
    per_edge[k] = std::max(0, static_cast<int>(std::lround(along.norm() / spacing)) - 1);
    count += per_edge[k] + 1;
  }
  BoundarySamples samples;
  samples.points.resize(count, 2);
  samples.normals.resize(count, 2);
  int row = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j <= per_edge[k]; ++j, ++row) {
      const double t = static_cast<double>(j) / (per_edge[k] + 1);
      samples.points.row(row) = (1 - t) * polygon.row(k) + t * polygon.row((k + 1) % n);
      const Eigen::Vector2d normal =
          j == 0 ? (edge_normals[k] + edge_normals[(k + n - 1) % n]).normalized().eval() : edge_normals[k];
      samples.normals.row(row) = normal.transpose();
      samples.edges.push_back(k);
      samples.parameters.push_back(t);
    }
  return samples;
}

// Whether x lies inside the polygon (even-odd rule) and its distance to the boundary.
std::pair<bool, double> locate(const Eigen::MatrixX2d& polygon, const Eigen::Vector2d& x) {
  const auto n = static_cast<int>(polygon.rows());
  bool inside = false;
  double distance = INFINITY;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d a = polygon.row(k), b = polygon.row((k + 1) % n);
    if ((a.y() > x.y()) != (b.y() > x.y()) && x.x() < a.x() + (x.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    distance = std::min(distance, (a + t * ab - x).norm());
  }
  return {inside, distance};
}

}  // namespace

FaceHarmonicCoordinates::FaceHarmonicCoordinates(const Eigen::MatrixXd& polygon, const MfsOptions& options)
    : polygon_(polygon) {
  const auto n = static_cast<int>(polygon.rows());
  if (n < 3 || polygon.cols() != 3)
    throw std::invalid_argument("FaceHarmonicCoordinates: a face needs >= 3 nodes in 3D");
  // A right-handed frame of the plane about the face normal, so the polygon is
  // counter-clockwise in (u, v).
  const Eigen::Vector3d normal = polygon_area_vector(polygon).normalized();
  origin_ = polygon.colwise().mean().transpose();
  axis_u_ = (polygon.row(1) - polygon.row(0)).transpose();
  axis_u_ = (axis_u_ - axis_u_.dot(normal) * normal).normalized();
  axis_v_ = normal.cross(axis_u_);
  scale_ = 1;
  scale_ = (to_plane(polygon).rowwise().norm()).maxCoeff();
  const Eigen::MatrixX2d local = to_plane(polygon);
  double diameter = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) diameter = std::max(diameter, (local.row(i) - local.row(j)).norm());

  // The sample spacing from the face's area (a square of side a: a / (edge_samples + 1),
  // the paper's 3-5 samples per edge, §5), so short edges add only what their length
  // holds; a sliver face (a cut cell's) from half its diameter instead, so it is not
  // sampled more densely than a square of its size.
  const double size = std::max(std::sqrt(std::abs(polygon_moments_2d(local, 0)[0])), diameter / 2);
  const double spacing = size / (options.edge_samples + 1);

  // Kernel centres: boundary samples moved outward by ξ·size (eq. (12)); a centre that
  // lands inside a non-convex polygon, or too close to it, is dropped, and so is one
  // closer than half a spacing to a centre kept before (close nodes of a cut face).
  // A triangle's harmonic coordinates are its barycentric ones, a rectangle's the bilinear
  // ones (Δ(uv) = 0 in the frame of its sides): the linear polynomial, plus uv on a
  // rectangle, fits the boundary data exactly without kernels. They are also the traces of
  // a neighbouring plain Tet4 / Hex8 cell's closed-form basis, so a sliced mesh's cut cells
  // and grid hexahedra share exact boundary data (the patch test under `basis: auto`).
  const bool triangle = n == 3;
  bilinear_ = n == 4;
  for (int k = 0; k < n && bilinear_; ++k) {
    const Eigen::Vector2d in = local.row(k) - local.row((k + n - 1) % n), out = local.row((k + 1) % n) - local.row(k);
    bilinear_ = std::abs(in.dot(out)) <= 1e-12 * in.squaredNorm() + 1e-12 * out.squaredNorm();
  }
  const BoundarySamples samples = sample_boundary(local, spacing);
  std::vector<Eigen::Vector2d> centres;
  for (Eigen::Index s = 0; s < samples.points.rows() && !triangle && !bilinear_; ++s) {
    const Eigen::Vector2d centre = samples.points.row(s) + options.offset * diameter * samples.normals.row(s);
    if (std::any_of(centres.begin(), centres.end(),
                    [&](const Eigen::Vector2d& kept) { return (kept - centre).norm() < spacing / 2; }))
      continue;
    const auto [inside, distance] = locate(local, centre);
    if (!inside && distance >= 0.5 * options.offset * diameter) centres.push_back(centre);
  }
  centres_.resize(static_cast<Eigen::Index>(centres.size()), 2);
  for (size_t j = 0; j < centres.size(); ++j) centres_.row(static_cast<Eigen::Index>(j)) = centres[j].transpose();

  // Least squares against the boundary data at m ≈ 3n collocation points (eqs. (13)-(14)).
  const BoundarySamples collocation = sample_boundary(local, spacing / options.collocation_factor);
  const Eigen::Index m = collocation.points.rows(), c = centres_.rows(), columns = c + polynomial_count();
  Eigen::MatrixXd augmented(m, columns + n);  // [system | data]
  auto system = augmented.leftCols(columns);
  auto data = augmented.rightCols(n);
  const auto fill_system = [&] {
    kernel_rows(collocation.points, system);
    data.setZero();
    for (Eigen::Index i = 0; i < m; ++i) {
      const int edge = collocation.edges[i];
      const double t = collocation.parameters[i];
      data(i, edge) += 1 - t;  // linear along the edge between its two nodes
      data(i, (edge + 1) % n) += t;
    }
  };
  fill_system();
  solve_mfs_least_squares(augmented, columns, fill_system, coefficients_);
}

Eigen::MatrixX2d FaceHarmonicCoordinates::to_plane(const Eigen::MatrixXd& points) const {
  Eigen::MatrixX2d local(points.rows(), 2);
  for (Eigen::Index p = 0; p < points.rows(); ++p) {
    const Eigen::Vector3d offset = points.row(p).transpose() - origin_;
    local.row(p) << offset.dot(axis_u_) / scale_, offset.dot(axis_v_) / scale_;
  }
  return local;
}

void FaceHarmonicCoordinates::kernel_rows(const Eigen::MatrixX2d& local, Eigen::Ref<Eigen::MatrixXd> rows) const {
  const Eigen::Index c = centres_.rows();
  // Column by column, vectorised over the points: log‖x − k‖ = ½ log‖x − k‖².
  for (Eigen::Index j = 0; j < c; ++j)
    rows.col(j) =
        0.5 *
        ((local.col(0).array() - centres_(j, 0)).square() + (local.col(1).array() - centres_(j, 1)).square()).log();
  rows.middleCols(c, 2) = local;
  rows.col(c + 2).setOnes();
  if (bilinear_) rows.col(c + 3) = local.col(0).cwiseProduct(local.col(1));
}

Eigen::MatrixXd FaceHarmonicCoordinates::evaluate(const Eigen::MatrixXd& points) const {
  Eigen::MatrixXd rows(points.rows(), centres_.rows() + polynomial_count());
  kernel_rows(to_plane(points), rows);
  return rows * coefficients_;
}

Eigen::MatrixX3d FaceHarmonicCoordinates::gradients(const Eigen::Vector3d& point) const {
  const Eigen::Vector2d x = to_plane(point.transpose()).row(0).transpose();
  const Eigen::Index c = centres_.rows();
  // d/dx of one row of evaluate()'s matrix, in the local scaled frame (2 × (#centres + 3)).
  Eigen::MatrixXd row_derivatives(2, c + polynomial_count());
  for (Eigen::Index j = 0; j < c; ++j) {
    const Eigen::Vector2d offset = x - centres_.row(j).transpose();
    row_derivatives.col(j) = offset / offset.squaredNorm();
  }
  row_derivatives.middleCols(c, 3) << 1, 0, 0, 0, 1, 0;
  if (bilinear_) row_derivatives.col(c + 3) << x.y(), x.x();
  const Eigen::MatrixX2d local = (row_derivatives * coefficients_).transpose();  // #nodes × 2
  // Back to space: local = ((x − origin)·u, (x − origin)·v) / scale.
  return (local.col(0) * axis_u_.transpose() + local.col(1) * axis_v_.transpose()) / scale_;
}

}  // namespace altfem::harmonic
