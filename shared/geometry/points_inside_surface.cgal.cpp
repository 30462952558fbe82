#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include "shared/geometry/points_inside_surface.hpp"

namespace altfem {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
}  // namespace

std::vector<SurfaceSide> points_inside_surface(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles,
                                               const Eigen::MatrixXd& points) {
  Mesh mesh;
  std::vector<Mesh::Vertex_index> handles(static_cast<std::size_t>(vertices.rows()));
  for (Eigen::Index v = 0; v < vertices.rows(); ++v)
    handles[v] = mesh.add_vertex(Point(vertices(v, 0), vertices(v, 1), vertices(v, 2)));
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
    mesh.add_face(handles[triangles(t, 0)], handles[triangles(t, 1)], handles[triangles(t, 2)]);
  // The AABB tree is built on the first query behind an atomic (CGAL_HAS_THREADS), so the
  // const queries below may run in parallel.
  const CGAL::Side_of_triangle_mesh<Mesh, Kernel> side_of(mesh);
  std::vector<SurfaceSide> sides(static_cast<std::size_t>(points.rows()));
  const int count = static_cast<int>(points.rows());
#pragma omp parallel for schedule(static)
  for (int i = 0; i < count; ++i) {
    const CGAL::Bounded_side side = side_of(Point(points(i, 0), points(i, 1), points(i, 2)));
    sides[i] = side == CGAL::ON_BOUNDED_SIDE     ? SurfaceSide::inside
               : side == CGAL::ON_UNBOUNDED_SIDE ? SurfaceSide::outside
                                                 : SurfaceSide::on_surface;
  }
  return sides;
}

}  // namespace altfem
