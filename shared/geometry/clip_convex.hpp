#pragma once
// Clipping a tetrahedron by a convex polyhedron given as half-spaces, the geometric
// kernel of intersection quadrature (Longva et al. 2020, §4.5): the intersection of
// two convex polyhedra is convex, so it is tetrahedralised by a fan from its
// centroid. Every in/out/on decision is an exact orientation predicate (CGAL's
// Epick kernel) on the points' double coordinates, so a face of the tetrahedron
// that lies in a clipping plane, or a vertex on it, is classified "on" exactly:
// two cells sharing that plane neither both keep nor both drop the volume. A plane with
// every vertex of one side within 1e-14 of the piece's diagonal of it (a corner rounded a
// few ulps off a cell's face or edge) leaves the piece to the other side whole: cutting
// there made vertices a few ulps apart, through which the next plane folded the piece.
#include <Eigen/Core>
#include <array>
#include <vector>

namespace altfem {

/// The plane through three points a, b, c; the kept side is where the points
/// (a, b, c, x) are negatively oriented, i.e. behind (b − a) × (c − a). For a convex
/// polyhedron's face listed counter-clockwise seen from outside, that is the inside.
struct ClipPlane {
  Eigen::Vector3d a, b, c;
};

/// A tetrahedron: 4 × 3, one vertex per row.
using TetrahedronCorners = Eigen::Matrix<double, 4, 3>;

/// Where clip_tetrahedron's fan of a cut piece starts.
enum class PieceFan {
  /// The centroid of the piece's vertices: one tetrahedron per triangle of every face.
  centroid,
  /// One of its vertices: none for the faces through it, so fewer tetrahedra (about half
  /// for a piece shaped like a box), for rules that integrate their integrand exactly on
  /// any tetrahedralisation.
  vertex,
};

/// The tetrahedra of (tetrahedron ∩ every kept half-space), each positively
/// oriented (det[x1 − x0, x2 − x0, x3 − x0] > 0); empty when the intersection has
/// no volume. The pieces tile the intersection exactly up to rounding of the new
/// vertices (each an edge–plane intersection in double precision). A tetrahedron the
/// planes do not cut is returned whole, whatever the fan.
std::vector<TetrahedronCorners> clip_tetrahedron(const TetrahedronCorners& tetrahedron,
                                                 const std::vector<ClipPlane>& planes,
                                                 PieceFan fan = PieceFan::centroid);

/// The six planes of a hexahedron with planar faces and the four of a tetrahedron,
/// from its corners in VTK order (8 × 3 or 4 × 3), inside kept.
std::vector<ClipPlane> hexahedron_clip_planes(const Eigen::Ref<const Eigen::MatrixXd>& corners);
std::vector<ClipPlane> tetrahedron_clip_planes(const Eigen::Ref<const Eigen::MatrixXd>& corners);

/// Whether the four corners of every face of the hexahedron (8 × 3, VTK order) are
/// coplanar: exactly (an exact predicate), or with the fourth corner within
/// relative_tolerance × the face's size of the plane of the other three (corners
/// computed by a map are rounded). Clipping needs planar faces.
bool hexahedron_faces_planar(const Eigen::Ref<const Eigen::MatrixXd>& corners, double relative_tolerance = 1e-12);

}  // namespace altfem
