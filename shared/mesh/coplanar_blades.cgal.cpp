#include "shared/mesh/coplanar_blades.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <vector>

namespace altfem {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point2 = Kernel::Point_2;
using Polygon2 = CGAL::Polygon_2<Kernel>;

}  // namespace

std::optional<CuttingPlane> convex_union_blade(const CuttingPlane& a, const CuttingPlane& b) {
  if (a.polygon.size() < 3 || b.polygon.size() < 3 || a.surface || b.surface) return std::nullopt;
  double size = 0;
  for (const auto* blade : {&a, &b})
    for (const Eigen::Vector3d& corner : blade->polygon) size = std::max(size, (corner - a.polygon.front()).norm());
  const Eigen::Vector3d normal = a.normal.normalized();
  for (const Eigen::Vector3d& corner : b.polygon)
    if (std::abs(normal.dot(corner - a.point)) > 1e-9 * size) return std::nullopt;
  // Both in a's plane's coordinates (b's corners taken onto it: they lie on it to 1e-9),
  // exactly from there on; each 2D corner keeps its 3D corner.
  Eigen::Index smallest = 0;
  normal.cwiseAbs().minCoeff(&smallest);
  const Eigen::Vector3d first = normal.cross(Eigen::Vector3d::Unit(smallest)).normalized();
  const Eigen::Vector3d second = normal.cross(first);
  std::vector<std::pair<Point2, Eigen::Vector3d>> corners;
  const auto polygon_of = [&](const CuttingPlane& blade) {
    Polygon2 polygon;
    for (const Eigen::Vector3d& corner : blade.polygon) {
      polygon.push_back(Point2((corner - a.point).dot(first), (corner - a.point).dot(second)));
      corners.emplace_back(polygon.container().back(), corner);
    }
    if (polygon.is_clockwise_oriented()) polygon.reverse_orientation();
    return polygon;
  };
  const Polygon2 first_polygon = polygon_of(a), second_polygon = polygon_of(b);
  if (!first_polygon.is_simple() || !second_polygon.is_simple()) return std::nullopt;
  // Overlapping by an area: their intersection is not empty and not flat.
  std::vector<CGAL::Polygon_with_holes_2<Kernel>> common;
  CGAL::intersection(first_polygon, second_polygon, std::back_inserter(common));
  if (common.empty() || common.front().outer_boundary().area() == 0) return std::nullopt;
  CGAL::Polygon_with_holes_2<Kernel> joined;
  if (!CGAL::join(first_polygon, second_polygon, joined) || joined.has_holes()) return std::nullopt;
  // Its corners where it turns: convex when each turns the same way, and each one of the
  // blades' corners (a corner where the polygons' edges cross is a reflex one).
  const std::vector<Point2> boundary(joined.outer_boundary().vertices_begin(), joined.outer_boundary().vertices_end());
  std::vector<Eigen::Vector3d> union_corners;
  const std::size_t n = boundary.size();
  for (std::size_t k = 0; k < n; ++k) {
    const CGAL::Orientation turn = CGAL::orientation(boundary[(k + n - 1) % n], boundary[k], boundary[(k + 1) % n]);
    if (turn == CGAL::COLLINEAR) continue;
    if (turn == CGAL::RIGHT_TURN) return std::nullopt;
    const auto corner =
        std::find_if(corners.begin(), corners.end(), [&](const auto& known) { return known.first == boundary[k]; });
    if (corner == corners.end()) return std::nullopt;
    union_corners.push_back(corner->second);
  }
  if (union_corners.size() < 3) return std::nullopt;
  CuttingPlane result = polygon_blade(std::move(union_corners));
  result.piece_at = b.piece_at;
  result.sweep = b.sweep;
  return result;
}

}  // namespace altfem
