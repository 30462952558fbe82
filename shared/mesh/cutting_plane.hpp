#pragma once
// A blade: what a scene's `cut` event holds and what the meshes are cut by — the whole
// plane, a convex polygon in it (a finite blade: partial cuts and notches), or a
// triangulated surface (cut_by_surface.hpp).
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace altfem {

struct SurfaceBlade;

/// The plane through `point` with normal `normal` (not necessarily unit, non-zero). Its
/// positive side is where `normal` points. With `polygon` non-empty the blade is that
/// convex polygon of the plane (its corners in order, either way round, each on the plane
/// to 1e-9 of the polygon's size) and only what it covers separates.
struct CuttingPlane {
  CuttingPlane() = default;
  CuttingPlane(const Eigen::Vector3d& point, const Eigen::Vector3d& normal, std::vector<Eigen::Vector3d> polygon = {})
      : point(point), normal(normal), polygon(std::move(polygon)) {}

  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  std::vector<Eigen::Vector3d> polygon;
  /// When set, only the piece of the body (cells connected through faces, in the rest
  /// configuration) holding the node nearest this point is cut: what earlier cuts severed
  /// from it (a pencil's chips) is left whole.
  std::optional<Eigen::Vector3d> piece_at;
  /// The sweep this blade is a cut of (its event's JSON pointer), "" for a blade that does
  /// not sweep. A sweep's later blades cover its earlier ones (swept_blade), so cut_surface
  /// cuts the surface from before the sweep again rather than the one it notched.
  std::string sweep;
  /// When set, the blade is this triangulated surface (a cut event's `surface` file), not
  /// the plane: the cuts take it triangle by triangle (cut_by_surface.hpp).
  std::shared_ptr<const SurfaceBlade> surface;
};

/// The blade of the polygon `corners`: its plane through the first corner with the
/// polygon's Newell normal (its positive side the one the corners turn counter-clockwise
/// around seen from). Check it with blade_polygon_problem.
CuttingPlane polygon_blade(std::vector<Eigen::Vector3d> corners);

/// What the polygon of `blade` sweeps moving by `translation` in its plane: the convex
/// hull of it and its translate (its corners are theirs; corners where the hull runs
/// straight on are left out).
CuttingPlane swept_blade(const CuttingPlane& blade, const Eigen::Vector3d& translation);

/// Why `blade`'s polygon cannot be a blade ("" when it can, or when it has none): fewer
/// than 3 corners, corners not finite, off the plane, repeated, collinear, or a polygon
/// that is not convex.
std::string blade_polygon_problem(const CuttingPlane& blade);

/// A blade as the cut decides with it: its plane as three points a, b, c on it, (b − a) ×
/// (c − a) along the blade's normal, so that every side decision is one exact orientation
/// predicate against the same plane; and, for a polygon, its side planes (through each
/// edge and the edge moved along the normal), so that whether the blade covers a point of
/// its plane is exact too.
class ExactBlade {
public:
  /// Throws std::invalid_argument for a zero or non-finite normal or a polygon with a
  /// blade_polygon_problem.
  explicit ExactBlade(const CuttingPlane& blade);

  /// −1, 0, +1: the side of the plane `point` lies on.
  int side(const Eigen::Vector3d& point) const;
  /// Whether the blade covers `point`, a point of its plane: always for the whole plane,
  /// within the polygon or on its edges otherwise.
  bool covers(const Eigen::Vector3d& point) const;
  /// Whether the blade covers the point where it crosses the edge (p, q), whose ends lie
  /// strictly on either side of the plane (the crossing point constructed exactly).
  bool covers_crossing(const Eigen::Vector3d& p, const Eigen::Vector3d& q) const;
  bool whole_plane() const { return corners_.empty(); }

  Eigen::Vector3d a, b, c;
  Eigen::Vector3d normal;  ///< (b − a) × (c − a), for placing new nodes only

private:
  std::vector<Eigen::Vector3d> corners_, raised_;  ///< the polygon; each corner moved along the normal
  int inside_sign_ = 1;                            ///< the side planes' sign inside the polygon
};

}  // namespace altfem
