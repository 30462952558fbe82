#pragma once
// A planar region with holes as simple polygons, without new nodes (Eberly, "Triangulation
// by ear clipping", §3: hole bridging): what a face of a polyhedral mesh must be. The
// slicer's grid faces pierced by the surface (grid_face_region) and a cut's sections of
// cells that are rings around the blade's path (cut_polyhedral_mesh) need it.
#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

namespace altfem {

/// Simple polygons covering `outer` (node loops, counter-clockwise in the coordinates
/// `in_plane` gives each node) minus `holes` (clockwise, each inside one outer loop): each
/// hole is joined to its outer loop by two bridges between existing vertices — from its
/// vertex of largest u along +u and from its vertex of smallest u along −u, to a vertex
/// they see — which cut the ring into two simple polygons that share the bridges. Throws
/// NumericalError(`failure`) when a bridge would meet another hole first.
std::vector<std::vector<int>> split_holes(std::vector<std::vector<int>> outer,
                                          const std::vector<std::vector<int>>& holes,
                                          const std::function<Eigen::Vector2d(int)>& in_plane,
                                          const std::string& failure);

/// Coordinates in a plane with normal `normal` in which a loop counter-clockwise about
/// `normal` turns counter-clockwise: (u, v) along unit vectors with u × v = normal. The
/// function holds a reference to `points`.
std::function<Eigen::Vector2d(int)> plane_coordinates(const std::vector<Eigen::Vector3d>& points,
                                                      const Eigen::Vector3d& normal);

}  // namespace altfem
