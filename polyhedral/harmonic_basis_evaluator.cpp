#include "polyhedral/harmonic_basis_evaluator.hpp"

#include <algorithm>
#include <limits>

#include "shared/common/error.hpp"

namespace altfem::harmonic {

namespace {

double distance_to_segment(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - x).norm();
}

// Distance from x to a planar simple polygon (loop of mesh nodes, convex or not): to
// its plane when the projection falls inside (even-odd rule in the plane), else to the
// nearest edge.
double distance_to_polygon(const Eigen::MatrixXd& nodes, const std::vector<int>& loop, const Eigen::Vector3d& normal,
                           const Eigen::Vector3d& x) {
  const auto n = loop.size();
  const Eigen::Vector3d origin = nodes.row(loop[0]).transpose();
  const Eigen::Vector3d u = (nodes.row(loop[1]).transpose() - origin).normalized();
  const Eigen::Vector3d v = normal.cross(u);
  const Eigen::Vector2d p((x - origin).dot(u), (x - origin).dot(v));
  bool inside = false;
  double edge_distance = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d a3 = nodes.row(loop[k]).transpose(), b3 = nodes.row(loop[(k + 1) % n]).transpose();
    const Eigen::Vector2d a((a3 - origin).dot(u), (a3 - origin).dot(v)), b((b3 - origin).dot(u), (b3 - origin).dot(v));
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
    edge_distance = std::min(edge_distance, distance_to_segment(x, a3, b3));
  }
  return inside ? std::abs((x - origin).dot(normal)) : edge_distance;
}

}  // namespace

HarmonicBasisEvaluator::HarmonicBasisEvaluator(const PolyhedralMesh& mesh, const HarmonicElementBases& bases)
    : mesh_(mesh), bases_(bases), bounds_(static_cast<size_t>(bases.cell_count())) {
  for (int cell = 0; cell < bases.cell_count(); ++cell)
    for (int node : bases.nodes(cell)) bounds_[cell].extend(mesh.nodes.row(node).transpose());
}

double HarmonicBasisEvaluator::distance_to_boundary(int cell, const Eigen::Vector3d& x) const {
  double distance = std::numeric_limits<double>::infinity();
  for (int face : mesh_.cell_faces[cell])
    distance = std::min(distance,
                        distance_to_polygon(mesh_.nodes, mesh_.faces[face], mesh_.face_normals.row(face).transpose(), x));
  return distance;
}

bool HarmonicBasisEvaluator::evaluate(int cell, const Eigen::Vector3d& x, std::vector<int>& basis,
                                      std::vector<double>& values) const {
  Eigen::VectorXd cell_values;
  if (!bases_.evaluate(cell, x, cell_values)) return false;
  basis = bases_.nodes(cell);
  values.assign(cell_values.data(), cell_values.data() + cell_values.size());
  return true;
}

bool HarmonicBasisEvaluator::evaluate_inside(int cell, const Eigen::Vector3d& x, std::vector<int>& basis,
                                             std::vector<double>& values) const {
  const double tolerance = 1e-9 * mesh_.cell_diameters[cell];
  if (bounds_[cell].exteriorDistance(x) > tolerance) return false;
  if (winding_number(cell_polyhedron(mesh_, cell), x) <= 0.5 && distance_to_boundary(cell, x) > tolerance) return false;
  return evaluate(cell, x, basis, values);
}

double HarmonicBasisEvaluator::evaluate_nearest(const Eigen::Vector3d& x, std::vector<int>& basis,
                                                std::vector<double>& values) const {
  // The bounding-box distance bounds the boundary distance from below: only cells whose
  // box is nearer than the best so far are measured.
  std::vector<std::pair<double, int>> candidates;
  for (int cell = 0; cell < bases_.cell_count(); ++cell) candidates.emplace_back(bounds_[cell].exteriorDistance(x), cell);
  std::sort(candidates.begin(), candidates.end());
  // The nearest cell whose map can be inverted: a sliver next to the point cannot.
  std::vector<char> degenerate(candidates.size(), 0);
  for (;;) {
    double best = std::numeric_limits<double>::infinity();
    std::size_t nearest = candidates.size();
    for (std::size_t i = 0; i < candidates.size() && candidates[i].first < best; ++i) {
      if (degenerate[i]) continue;
      const double distance = distance_to_boundary(candidates[i].second, x);
      if (distance < best) best = distance, nearest = i;
    }
    if (nearest == candidates.size())
      throw NumericalError("harmonic embedding: no cell near a surface point has an invertible map");
    if (evaluate(candidates[nearest].second, x, basis, values)) return best;
    degenerate[nearest] = 1;
  }
}

}  // namespace altfem::harmonic
