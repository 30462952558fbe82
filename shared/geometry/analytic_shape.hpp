#pragma once
// Analytic solids given as level sets: box, sphere, (hollow) cylinder, and CSG of
// them (docs/scene-schema.md, "Analytic shapes"). The fem meshes them with CGAL
// Mesh_3's implicit-function domain, which calls level_set very often: it must be
// continuous and cheap.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace altfem {

/// A piecewise-linear curve; a closed one repeats its first point at the end.
using Polyline = std::vector<Eigen::Vector3d>;
/// Per axis, sorted coordinates of axis-aligned planes.
using AxisPlanes = std::array<std::vector<double>, 3>;
/// A planar rectangle {origin + s·u + t·v : s, t ∈ [0, 1]} (u ⟂ v), e.g. a box face.
struct PlanarFace {
  Eigen::Vector3d origin, u, v;
};

class AnalyticShape {
public:
  virtual ~AnalyticShape() = default;
  /// Negative inside, positive outside, zero on the surface. Primitives give the
  /// exact signed distance; CSG the min/max combination of its children's, which
  /// keeps the sign right and the function 1-Lipschitz (|level_set| never exceeds
  /// the distance to the surface).
  virtual double level_set(const Eigen::Vector3d& x) const = 0;
  /// Closed set: the surface belongs to the shape.
  bool contains(const Eigen::Vector3d& x) const { return level_set(x) <= 0.0; }
  /// A box that contains the shape; tight for primitives.
  virtual Eigen::AlignedBox3d bounding_box() const = 0;
  /// The volume in closed form, or nullopt when it has none (general CSG).
  virtual std::optional<double> exact_volume() const = 0;
  /// True only when the shape is known to be convex (used by CSG to prove nesting).
  virtual bool is_convex() const { return false; }
  /// The size of the shape's smallest part: a box's shortest side, a sphere's radius, a
  /// cylinder's radius or height, a tube's wall; a CSG's smallest child's. Mesh_3's
  /// criteria are held below it (tetrahedralize.hpp).
  virtual double smallest_feature() const = 0;
  /// When the shape is built from axis-aligned boxes only: the planes that hold its whole
  /// surface, so that it is exactly a union of cells of the rectilinear grid through
  /// them (tetrahedralize_box_shape). nullopt for any shape with a curved part.
  virtual std::optional<AxisPlanes> axis_planes() const { return std::nullopt; }
  /// The sharp edges of the surface (a box's 12 edges, a cylinder's rims), sampled at
  /// most `spacing` apart, for Mesh_3 to protect. A CSG keeps its children's edges
  /// where they lie on its surface, and adds the curves where one child's planar face
  /// meets another child's surface (a half-ball's rim: feature_curves.hpp); curves
  /// between two curved surfaces (a cylinder through a sphere) are not included.
  virtual std::vector<Polyline> sharp_edges(double /*spacing*/) const { return {}; }
  /// The planar faces of the surface that are rectangles (a box's six); CSG: its
  /// children's, which may reach beyond its own surface.
  virtual std::vector<PlanarFace> planar_faces() const { return {}; }
  /// exact_volume() if known, else integrate_volume(*this, volume_tolerance).
  double volume() const;

  static constexpr double volume_tolerance = 1e-4;
};

using ShapePointer = std::shared_ptr<const AnalyticShape>;

/// Axis-aligned box; requires min < max in every component.
ShapePointer make_box(const Eigen::Vector3d& min, const Eigen::Vector3d& max);
ShapePointer make_sphere(const Eigen::Vector3d& centre, double radius);
/// Cylinder whose bottom disc is centred at `base`, extending `height` along `axis`
/// (normalised here). inner_radius > 0 makes it hollow (a tube with open bore).
ShapePointer make_cylinder(const Eigen::Vector3d& base, const Eigen::Vector3d& axis, double height, double radius,
                           double inner_radius = 0.0);
/// CSG of at least two shapes. difference is the first minus all the others.
ShapePointer make_union(std::vector<ShapePointer> children);
ShapePointer make_intersection(std::vector<ShapePointer> children);
ShapePointer make_difference(std::vector<ShapePointer> children);
/// The shape mapped by x ↦ scale·x + translate (scale > 0).
ShapePointer make_scaled_translated(ShapePointer shape, double scale, const Eigen::Vector3d& translate);

/// Volume of {level_set <= 0} by an adaptive octree over the bounding box: cells the
/// level set proves fully inside or outside (|φ(centre)| ≥ half-diagonal) are exact,
/// leaves on the surface count the inside fraction of the linearised level set, and
/// the depth grows until three successive depths agree to `relative_tolerance`.
/// Throws NumericalError if that takes deeper than 10 levels.
double integrate_volume(const AnalyticShape& shape, double relative_tolerance);

}  // namespace altfem
