#include "shared/simulation/surface_traction.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "shared/common/error.hpp"
#include "shared/mesh/point_locator.hpp"
#include "shared/quadrature/reference_rules.hpp"
#include "shared/simulation/method_instance.hpp"

namespace altfem {

namespace {

// The highest total degree a basis of altfem has on a plane: Hex27's triquadratic
// functions restricted to an arbitrary plane (x²y²z² → degree 6). Tet20 and DG k = 3
// are cubic, Hex20 quartic there; harmonic bases are not polynomials, and converge.
constexpr int triangle_strength = 6;
// On a lifted (curved) triangle the integrand is φ_a times the area vector: on a Hex27
// face, degree 4 times degree 6 in the triangle's coordinates.
constexpr int lifted_triangle_strength = 10;

using Polygon = std::vector<Eigen::Vector3d>;

double polygon_area(const Polygon& polygon) {
  Eigen::Vector3d twice = Eigen::Vector3d::Zero();
  for (size_t i = 1; i + 1 < polygon.size(); ++i) twice += (polygon[i] - polygon[0]).cross(polygon[i + 1] - polygon[0]);
  return 0.5 * twice.norm();
}

// Sutherland–Hodgman: the part of a convex polygon in `box`. Signed distances within
// `slack` of a face count as on it, so a triangle lying in a cell's face stays whole
// and both cells of a shared plane cut at the same place.
Polygon clip_to_box(Polygon polygon, const Eigen::AlignedBox3d& box, double slack) {
  for (int axis = 0; axis < 3 && !polygon.empty(); ++axis)
    for (int side = 0; side < 2 && !polygon.empty(); ++side) {
      // d ≤ 0 inside: x_axis − max ≤ 0, or min − x_axis ≤ 0.
      const auto distance = [&](const Eigen::Vector3d& x) {
        const double d = side == 0 ? x[axis] - box.max()[axis] : box.min()[axis] - x[axis];
        return std::abs(d) <= slack ? 0.0 : d;
      };
      Polygon clipped;
      for (size_t i = 0; i < polygon.size(); ++i) {
        const Eigen::Vector3d& a = polygon[i];
        const Eigen::Vector3d& b = polygon[(i + 1) % polygon.size()];
        const double da = distance(a), db = distance(b);
        if (da <= 0) clipped.push_back(a);
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) clipped.push_back(a + da / (da - db) * (b - a));
      }
      polygon = std::move(clipped);
    }
  return polygon;
}

// The triangle as pieces, one per cell it crosses, when the cells' boxes tile it (their
// areas sum to the triangle's); else the triangle whole. Box cells (fcm's background
// grid) tile; tetrahedra's boxes overlap, and a triangle leaving every cell is not
// covered: those keep the triangle, whose points the embedding locates one by one.
std::vector<Polygon> cell_pieces(const Polygon& triangle, const PointLocator& locator, double slack,
                                 std::vector<int>& candidates) {
  const double area = polygon_area(triangle);
  const Eigen::Vector3d centroid = (triangle[0] + triangle[1] + triangle[2]) / 3;
  double radius = 0;
  for (const Eigen::Vector3d& vertex : triangle) radius = std::max(radius, (vertex - centroid).norm());
  locator.candidates(centroid, radius + slack, candidates);
  std::vector<Polygon> pieces;
  double covered = 0;
  for (int cell : candidates) {
    Polygon piece = clip_to_box(triangle, locator.box(cell), slack);
    const double piece_area = piece.size() >= 3 ? polygon_area(piece) : 0.0;
    if (piece_area <= 1e-10 * area) continue;
    covered += piece_area;
    pieces.push_back(std::move(piece));
  }
  if (std::abs(covered - area) <= 1e-9 * area) return pieces;
  return {triangle};
}

}  // namespace

SurfacePoints surface_load_points(const SurfaceMesh& surface, const SurfaceTraction& load,
                                  const ElementBasisEvaluator& evaluator, double tolerance, const std::string& file,
                                  const SurfaceLift& lift) {
  std::vector<Eigen::AlignedBox3d> boxes(static_cast<size_t>(evaluator.element_count()));
  for (int e = 0; e < evaluator.element_count(); ++e) boxes[e] = evaluator.element_bounds(e);
  const PointLocator locator(std::move(boxes));
  const double slack = 1e-9 * (surface.vertices.colwise().maxCoeff() - surface.vertices.colwise().minCoeff()).norm();
  // Weights sum to 1/2.
  const QuadratureRule rule = triangle_rule(lift ? lifted_triangle_strength : triangle_strength);

  std::vector<Eigen::Vector3d> points, normals;
  std::vector<double> weights;
  std::vector<int> candidates;
  int selected = 0;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    const Polygon triangle{surface.vertices.row(surface.triangles(t, 0)).transpose(),
                           surface.vertices.row(surface.triangles(t, 1)).transpose(),
                           surface.vertices.row(surface.triangles(t, 2)).transpose()};
    if (!load.region.contains((triangle[0] + triangle[1] + triangle[2]) / 3, tolerance)) continue;
    ++selected;
    if (lift) {
      Eigen::Vector3d point, area_vector;
      for (Eigen::Index q = 0; q < rule.weights.size(); ++q) {
        const double xi = rule.points(q, 0), eta = rule.points(q, 1);
        lift(static_cast<int>(t), Eigen::Vector3d(1 - xi - eta, xi, eta), point, area_vector);
        points.push_back(point);
        normals.push_back(area_vector.normalized());
        weights.push_back(rule.weights[q] * area_vector.norm());
      }
      continue;
    }
    const Eigen::Vector3d normal = (triangle[1] - triangle[0]).cross(triangle[2] - triangle[0]).normalized();
    for (const Polygon& piece : cell_pieces(triangle, locator, slack, candidates))
      for (size_t i = 1; i + 1 < piece.size(); ++i) {  // a fan over the convex piece
        const Eigen::Vector3d edge1 = piece[i] - piece[0], edge2 = piece[i + 1] - piece[0];
        const double jacobian = edge1.cross(edge2).norm();  // twice the area: the rule's weights sum to 1/2
        for (Eigen::Index q = 0; q < rule.weights.size(); ++q) {
          points.push_back(piece[0] + rule.points(q, 0) * edge1 + rule.points(q, 1) * edge2);
          normals.push_back(normal);
          weights.push_back(rule.weights[q] * jacobian);
        }
      }
  }
  if (selected == 0)
    throw InputError(input_message(file, load.pointer + "/region",
                                   "holds the centroid of no triangle of the loaded surface (" +
                                       std::to_string(surface.triangles.rows()) +
                                       " triangles: the scene's surface, else the method's mesh boundary)"));
  const auto count = static_cast<Eigen::Index>(points.size());
  SurfacePoints result{Eigen::MatrixXd(count, 3), Eigen::MatrixXd(count, 3), Eigen::VectorXd(count)};
  for (Eigen::Index q = 0; q < count; ++q) {
    result.points.row(q) = points[q].transpose();
    result.normals.row(q) = normals[q].transpose();
    result.weights[q] = weights[q];
  }
  return result;
}

Eigen::MatrixXd surface_forces(const SurfaceTraction& load, const SurfacePoints& points, double time) {
  // docs/conventions.md, "Surface loads": a pressure acts along the inward normal.
  Eigen::MatrixXd tractions;
  if (load.traction) tractions = load.traction->transpose().replicate(points.points.rows(), 1);
  else if (load.traction_field.has_value())
    tractions = load.traction_field.evaluate(points.points, points.normals, time);
  else tractions = -load.pressure * points.normals;
  return points.weights.asDiagonal() * tractions;
}

SurfaceTractionLoad::SurfaceTractionLoad(const std::vector<SurfaceTraction>& loads, const SurfaceMesh& surface,
                                         const ElementBasisEvaluator& evaluator, int dof_count, double tolerance,
                                         const std::string& file, const SurfaceLift& lift)
    : loads_(loads), vectors_(Eigen::MatrixXd::Zero(dof_count, static_cast<Eigen::Index>(loads.size()))) {
  for (size_t i = 0; i < loads.size(); ++i) {
    SurfacePoints points = surface_load_points(surface, loads[i], evaluator, tolerance, file, lift);
    auto embedding = std::make_shared<const BasisEmbedding>(evaluator, points.points);
    if (loads[i].traction_field.has_value() && loads[i].traction_field.depends_on_time())
      time_dependent_.push_back({static_cast<int>(i), std::move(points), std::move(embedding)});
    else vectors_.col(static_cast<Eigen::Index>(i)) = embedding->load(surface_forces(loads[i], points, 0.0), dof_count);
  }
}

Eigen::VectorXd SurfaceTractionLoad::operator()(double time) const {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(vectors_.rows());
  for (size_t i = 0; i < loads_.size(); ++i)
    load += loads_[i].factor(time) * vectors_.col(static_cast<Eigen::Index>(i));
  for (const TimeDependentLoad& entry : time_dependent_)
    load +=
        loads_[entry.load].factor(time) *
        entry.embedding->load(surface_forces(loads_[entry.load], entry.points, time), static_cast<int>(load.size()));
  return load;
}

std::function<Eigen::VectorXd(double)> surface_traction_load(const Scene& scene,
                                                             const Eigen::AlignedBox3d& geometry_bounds,
                                                             const MethodInstance& method) {
  if (scene.tractions.empty()) return {};
  return SurfaceTractionLoad(scene.tractions, method.load_surface(), method.basis_evaluator(),
                             method.discretization().dof_count(), region_tolerance(geometry_bounds),
                             scene.file.string(), method.surface_lift());
}

}  // namespace altfem
