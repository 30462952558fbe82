#pragma once
// The cut curve a plane leaves on a closed surface, cleaned before its cap is remeshed
// (cut_surface, issue #33). Only cut_surface's CGAL files include it.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Core>
#include <functional>

namespace altfem::cut_curve {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
/// Each vertex carries "v:input": its index in the surface before the cut, −1 for a point
/// the cut added.
using Mesh = CGAL::Surface_mesh<Point>;

inline Point point_of(const Eigen::Vector3d& x) { return {x.x(), x.y(), x.z()}; }
inline Eigen::Vector3d vector_of(const Point& p) { return {p.x(), p.y(), p.z()}; }

/// The points a plane cut added to `mesh` (one side, split and capped), `on_plane` telling
/// the cut's points (and the input's on the plane) from the rest: a new point of the curve
/// whose faces off the cap all lie in one plane (it crosses an edge inside a flat region,
/// e.g. an earlier cap) collapses onto a neighbour on the curve, where no face around it
/// turns over and no edge grows longer than `longest`: the region keeps its shape and the
/// curve only the points where it bends, or which keep the edges short. (Points a plane
/// adds within rounding of a vertex are not made: split_surface_by_plane takes the vertex
/// on the plane.)
void clean(Mesh& mesh, const std::function<bool(Mesh::Vertex_index)>& on_plane, double longest);

/// The faces of `mesh` that `in_cap` selects, remeshed to edges of about `length` with their
/// border kept: a cap triangulated from its boundary alone has long edges across it, which
/// the next cut crosses one by one, so that the points of the cut curve multiply with
/// every cut through the same place.
void remesh_cap(Mesh& mesh, const std::function<bool(Mesh::Face_index)>& in_cap, double length);

}  // namespace altfem::cut_curve
