#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <vector>

#include "shared/mesh/surface_projection.hpp"

namespace altfem {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
}  // namespace

struct SurfaceProjection::Tree {
  std::vector<Triangle> triangles;
  AabbTree tree;
};

SurfaceProjection::SurfaceProjection(const SurfaceMesh& surface) : tree_(std::make_unique<Tree>()) {
  const auto point = [&](int vertex) {
    return Kernel::Point_3(surface.vertices(vertex, 0), surface.vertices(vertex, 1), surface.vertices(vertex, 2));
  };
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t)
    tree_->triangles.emplace_back(point(surface.triangles(t, 0)), point(surface.triangles(t, 1)),
                                  point(surface.triangles(t, 2)));
  tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
  tree_->tree.accelerate_distance_queries();
}

SurfaceProjection::~SurfaceProjection() = default;

Eigen::Vector3d SurfaceProjection::closest_point(const Eigen::Vector3d& x) const {
  const Kernel::Point_3 closest = tree_->tree.closest_point(Kernel::Point_3(x.x(), x.y(), x.z()));
  return {closest.x(), closest.y(), closest.z()};
}

std::pair<Eigen::Vector3d, Eigen::Index> SurfaceProjection::closest_point_and_triangle(const Eigen::Vector3d& x) const {
  const auto [closest, triangle] = tree_->tree.closest_point_and_primitive(Kernel::Point_3(x.x(), x.y(), x.z()));
  return {{closest.x(), closest.y(), closest.z()}, triangle - tree_->triangles.cbegin()};
}

}  // namespace altfem
