#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "shared/geometry/exact_orientation.hpp"

namespace altfem {
namespace {

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

Point to_point(const Eigen::Vector3d& x) { return Point(x.x(), x.y(), x.z()); }

}  // namespace

int orientation_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                     const Eigen::Vector3d& d) {
  return static_cast<int>(CGAL::orientation(to_point(a), to_point(b), to_point(c), to_point(d)));
}

bool collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return CGAL::collinear(to_point(a), to_point(b), to_point(c));
}

}  // namespace altfem
