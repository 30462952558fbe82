#pragma once
// CGAL's exact orientation predicates on double coordinates, for code that decides
// topology (which side of a blade a node lies on, whether a cell is convex) without
// seeing CGAL's headers: the answer is that of the points as stored, never of a
// rounded difference, so a node exactly on a plane is "on" from every cell that holds it.
#include <Eigen/Core>

namespace altfem {

/// The sign (−1, 0, +1) of det[b − a, c − a, d − a]: +1 when d lies on the side of the
/// plane through a, b, c that (b − a) × (c − a) points to, 0 when the four are coplanar.
int orientation_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                     const Eigen::Vector3d& d);

/// orientation_sign(d, e, f, x) for the point x where the line through p and q meets the
/// plane through a, b, c (p and q strictly on either side of that plane), x constructed
/// exactly: on which side of a second plane a blade's crossing point of an edge lies.
int crossing_orientation_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                              const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& d,
                              const Eigen::Vector3d& e, const Eigen::Vector3d& f);

/// Whether a, b, c lie on one line (two or three of them equal included).
bool collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace altfem
