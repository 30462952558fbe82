// The only translation unit with CGAL Mesh_3 (docs/environment.md: ~2 minutes and ~4 GB
// to compile). CGAL over a mesher of our own: Mesh_3's Delaunay refinement gives
// bounded radius–edge ratios and a surface approximation with guarantees.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_domain_with_polyline_features_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <algorithm>
#include <array>
#include <map>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/mesh/snap_to_planar_faces.hpp"
#include "shared/mesh/tetrahedralize.hpp"

namespace altfem {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using CgalSurface = CGAL::Surface_mesh<Point>;

// Complex: Mesh_complex_3_in_triangulation_3 over the domain's triangulation (with
// the domain's corner and curve indices when it protects features).
// cell_size 0 leaves the cells' size free (CGAL's convention).
template <typename Complex, typename Domain>
VolumeMesh mesh_domain(const Domain& domain, double size, double cell_size) {
  using Criteria = CGAL::Mesh_criteria_3<typename Complex::Triangulation>;
  namespace parameters = CGAL::parameters;
  if (!(size > 0)) throw InputError("tetrahedralize: max_cell_size must be > 0");
  CGAL::get_default_random() = CGAL::Random(0);
  // edge_size only acts on protected features.
  const Criteria criteria(parameters::edge_size = size, parameters::facet_angle = 25, parameters::facet_size = size,
                          parameters::facet_distance = size / 10, parameters::cell_radius_edge_ratio = 3,
                          parameters::cell_size = cell_size);
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
    vertices.push_back(
        cgal_surface.add_vertex(Point(surface.vertices(v, 0), surface.vertices(v, 1), surface.vertices(v, 2))));
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t)
    cgal_surface.add_face(vertices[surface.triangles(t, 0)], vertices[surface.triangles(t, 1)],
                          vertices[surface.triangles(t, 2)]);
  using Domain = CGAL::Polyhedral_mesh_domain_3<CgalSurface, Kernel>;
  using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
  const Domain domain(cgal_surface);
  return mesh_domain<CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>>(domain, max_cell_size, max_cell_size);
}

VolumeMesh tetrahedralize_shape(const AnalyticShape& shape, double max_cell_size, bool bound_cells) {
  using ImplicitDomain = CGAL::Labeled_mesh_domain_3<Kernel>;
  using Domain = CGAL::Mesh_domain_with_polyline_features_3<ImplicitDomain>;
  using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
  using Complex = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation, Domain::Corner_index, Domain::Curve_index>;
  const Eigen::AlignedBox3d box = shape.bounding_box();
  const Eigen::Vector3d centre = box.center();
  const double radius = 0.5 * box.diagonal().norm() * 1.05;
  // A mesh coarser than the shape's thinnest part cannot represent it.
  const double size = std::min(max_cell_size, shape.smallest_feature());
  auto level_set = [&shape](const Point& p) { return shape.level_set(Eigen::Vector3d(p.x(), p.y(), p.z())); };
  Domain domain(ImplicitDomain::create_implicit_mesh_domain(
      level_set, Kernel::Sphere_3(Point(centre.x(), centre.y(), centre.z()), radius * radius),
      CGAL::parameters::relative_error_bound = 1e-7));
  // Features sampled finely against the size so that the polylines follow curved rims.
  std::vector<std::vector<Point>> polylines;
  for (const Polyline& edge : shape.sharp_edges(size / 4)) {
    std::vector<Point>& line = polylines.emplace_back();
    for (const Eigen::Vector3d& x : edge) line.emplace_back(x.x(), x.y(), x.z());
  }
  domain.add_features(polylines.begin(), polylines.end());
  VolumeMesh mesh = mesh_domain<Complex>(domain, size, bound_cells ? size : 0.0);
  // Mesh_3's vertices on a flat face lie on it to the level set's error bound only.
  snap_to_planar_faces(mesh, shape.planar_faces(), 1e-6 * box.diagonal().norm());
  return mesh;
}

}  // namespace altfem
