#pragma once
// Which side of a closed triangle surface points lie on, by CGAL's exact-predicate ray
// shooting (Side_of_triangle_mesh over an AABB tree): what grid slicing needs to tell
// the uncut grid cells inside the object from those outside.
#include <Eigen/Core>
#include <vector>

namespace altfem {

enum class SurfaceSide : signed char { outside = -1, on_surface = 0, inside = 1 };

/// For each row of `points` (#points × 3), its side of the closed, outward-oriented
/// surface (`vertices` #vertices × 3, `triangles` #triangles × 3). Queries run in parallel.
std::vector<SurfaceSide> points_inside_surface(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles,
                                               const Eigen::MatrixXd& points);

}  // namespace altfem
