#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <stdexcept>

#include "shared/geometry/exact_orientation.hpp"

namespace altfem {
namespace {

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

Point to_point(const Eigen::Vector3d& x) { return Point(x.x(), x.y(), x.z()); }

using Exact = CGAL::Exact_predicates_exact_constructions_kernel;

Exact::Point_3 to_exact(const Eigen::Vector3d& x) { return Exact::Point_3(x.x(), x.y(), x.z()); }

}  // namespace

int orientation_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                     const Eigen::Vector3d& d) {
  return static_cast<int>(CGAL::orientation(to_point(a), to_point(b), to_point(c), to_point(d)));
}

int crossing_orientation_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                              const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& d,
                              const Eigen::Vector3d& e, const Eigen::Vector3d& f) {
  const auto crossing = CGAL::intersection(Exact::Plane_3(to_exact(a), to_exact(b), to_exact(c)),
                                           Exact::Line_3(to_exact(p), to_exact(q)));
  const Exact::Point_3* point = crossing ? boost::get<Exact::Point_3>(&*crossing) : nullptr;
  if (point == nullptr)
    throw std::invalid_argument("crossing_orientation_sign: the line does not cross the plane once");
  return static_cast<int>(CGAL::orientation(to_exact(d), to_exact(e), to_exact(f), *point));
}

bool collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return CGAL::collinear(to_point(a), to_point(b), to_point(c));
}

}  // namespace altfem
