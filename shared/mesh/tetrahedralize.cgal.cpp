// The only translation unit with CGAL Mesh_3 (docs/environment.md: ~2 minutes and ~4 GB
// to compile). CGAL over a mesher of our own: Mesh_3's Delaunay refinement gives
// bounded radius–edge ratios and a surface approximation with guarantees.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <array>
#include <map>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/mesh/tetrahedralize.hpp"

namespace altfem {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using CgalSurface = CGAL::Surface_mesh<Point>;

template <typename Domain>
VolumeMesh mesh_domain(const Domain& domain, double size) {
  using Triangulation = typename CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
  using Complex = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>;
  using Criteria = CGAL::Mesh_criteria_3<Triangulation>;
  namespace parameters = CGAL::parameters;
  if (!(size > 0)) throw InputError("tetrahedralize: max_cell_size must be > 0");
  CGAL::get_default_random() = CGAL::Random(0);
  const Criteria criteria(parameters::facet_angle = 25, parameters::facet_size = size,
                          parameters::facet_distance = size / 10, parameters::cell_radius_edge_ratio = 3,
                          parameters::cell_size = size);
  const Complex complex =
      CGAL::make_mesh_3<Complex>(domain, criteria, parameters::no_perturb(), parameters::no_exude());

  VolumeMesh mesh;
  mesh.element_type = ElementType::tet4;
  std::map<typename Complex::Vertex_handle, int> index;
  std::vector<Point> points;
  std::vector<std::array<int, 4>> cells;
  for (auto cell = complex.cells_in_complex_begin(); cell != complex.cells_in_complex_end(); ++cell) {
    std::array<int, 4> tet{};
    for (int c = 0; c < 4; ++c) {
      auto [entry, inserted] = index.try_emplace(cell->vertex(c), static_cast<int>(points.size()));
      if (inserted) points.push_back(cell->vertex(c)->point().point());
      tet[c] = entry->second;
    }
    if (CGAL::orientation(points[tet[0]], points[tet[1]], points[tet[2]], points[tet[3]]) == CGAL::NEGATIVE)
      std::swap(tet[1], tet[2]);
    cells.push_back(tet);
  }
  if (cells.empty()) throw InputError("tetrahedralize: Mesh_3 produced no tetrahedra; max_cell_size may be too large");
  mesh.nodes.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i)
    mesh.nodes.row(static_cast<Eigen::Index>(i)) << points[i].x(), points[i].y(), points[i].z();
  mesh.cells.resize(static_cast<Eigen::Index>(cells.size()), 4);
  for (size_t i = 0; i < cells.size(); ++i)
    for (int c = 0; c < 4; ++c) mesh.cells(static_cast<Eigen::Index>(i), c) = cells[i][c];
  return mesh;
}

}  // namespace

VolumeMesh tetrahedralize_surface(const SurfaceMesh& surface, double max_cell_size) {
  CgalSurface cgal_surface;
  std::vector<CgalSurface::Vertex_index> vertices;
  for (Eigen::Index v = 0; v < surface.vertices.rows(); ++v)
    vertices.push_back(cgal_surface.add_vertex(Point(surface.vertices(v, 0), surface.vertices(v, 1), surface.vertices(v, 2))));
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t)
    cgal_surface.add_face(vertices[surface.triangles(t, 0)], vertices[surface.triangles(t, 1)],
                          vertices[surface.triangles(t, 2)]);
  const CGAL::Polyhedral_mesh_domain_3<CgalSurface, Kernel> domain(cgal_surface);
  return mesh_domain(domain, max_cell_size);
}

VolumeMesh tetrahedralize_shape(const AnalyticShape& shape, double max_cell_size) {
  using Domain = CGAL::Labeled_mesh_domain_3<Kernel>;
  const Eigen::AlignedBox3d box = shape.bounding_box();
  const Eigen::Vector3d centre = box.center();
  const double radius = 0.5 * box.diagonal().norm() * 1.05;
  auto level_set = [&shape](const Point& p) { return shape.level_set(Eigen::Vector3d(p.x(), p.y(), p.z())); };
  const Domain domain = Domain::create_implicit_mesh_domain(
      level_set, Kernel::Sphere_3(Point(centre.x(), centre.y(), centre.z()), radius * radius),
      CGAL::parameters::relative_error_bound = 1e-7);
  return mesh_domain(domain, max_cell_size);
}

}  // namespace altfem
