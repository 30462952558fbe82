#pragma once
// Loading the geometry a scene names, in world coordinates (scale and translate
// applied), with the checks that need it.
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "shared/geometry/analytic_shape.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/scene/scene.hpp"

namespace altfem {

struct SceneGeometry {
  std::string scene_file;              ///< the scene that names it, for messages
  std::optional<SurfaceMesh> surface;  ///< surface kind
  std::optional<VolumeMesh> mesh;      ///< mesh kind
  ShapePointer shape;                  ///< shape kind, already scaled and translated
  /// Shape kind: a fine closed surface of the shape (facets of min(diagonal / 40,
  /// smallest feature / 2), exact for box-built shapes), the same for every method.
  std::optional<SurfaceMesh> shape_surface;
  Eigen::AlignedBox3d bounds;
  /// Enclosed volume: exact for analytic primitives (else AnalyticShape::volume), by the
  /// divergence theorem for surfaces, and the sum of the straight-sided cells (corner
  /// tetrahedra; hexahedra split in 6) for volume meshes.
  double volume = 0.0;
  bool closed = true;  ///< surfaces are checked closed and manifold by read_surface
  bool manifold = true;
  std::vector<std::string> warnings;

  /// The surface every method deforms and `compare` measures on (docs/conventions.md,
  /// "Metrics"): the scene's surface or its shape's; nullptr for a volume mesh, whose
  /// methods each deform their own mesh's boundary.
  const SurfaceMesh* common_surface() const { return surface ? &*surface : shape_surface ? &*shape_surface : nullptr; }
};

/// Reads the surface or volume mesh (or builds the shape), applies scale/translate,
/// and checks that every Dirichlet and surface-load
/// region selects at least one point of the geometry (surface vertices, mesh nodes,
/// or sample points inside the analytic shape). Throws InputError naming the file
/// and e.g. /boundary_conditions/0/region.
SceneGeometry load_scene_geometry(const Scene& scene);

}  // namespace altfem
