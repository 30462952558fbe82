#include "shared/scene/scene_geometry.hpp"

#include <algorithm>
#include <array>

#include "shared/common/error.hpp"
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/tetrahedralize.hpp"

namespace altfem {

namespace {

Eigen::AlignedBox3d bounds_of(const Eigen::MatrixXd& points) {
  Eigen::AlignedBox3d box;
  for (Eigen::Index i = 0; i < points.rows(); ++i) box.extend(points.row(i).transpose().eval());
  return box;
}

double tetrahedron_volume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                          const Eigen::Vector3d& d) {
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

// Six tetrahedra around the diagonal 0–6 of a VTK-ordered hexahedron: exact for
// hexahedra with planar faces.
double cells_volume(const VolumeMesh& mesh) {
  constexpr std::array<std::array<int, 4>, 6> hex_split{
      {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}}};
  const bool hex = element_shape(mesh.element_type) == ElementShape::hexahedron;
  const auto node = [&](Eigen::Index cell, int local) {
    return mesh.nodes.row(mesh.cells(cell, local)).transpose().eval();
  };
  double volume = 0.0;
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell) {
    if (!hex) {
      volume += tetrahedron_volume(node(cell, 0), node(cell, 1), node(cell, 2), node(cell, 3));
      continue;
    }
    for (const auto& tet : hex_split)
      volume += tetrahedron_volume(node(cell, tet[0]), node(cell, tet[1]), node(cell, tet[2]), node(cell, tet[3]));
  }
  return volume;
}

void transform(Eigen::MatrixXd& points, double scale, const Eigen::Vector3d& translate) {
  points *= scale;
  points.rowwise() += translate.transpose();
}

// Does the region hold any point of the shape? Samples a 17³ grid (faces and
// centre included) of the part of the shape's box the region can reach.
bool region_meets_shape(const RegionSelector& region, const AnalyticShape& shape, double tolerance) {
  Eigen::AlignedBox3d box = shape.bounding_box();
  box = box.intersection(
      Eigen::AlignedBox3d(region.bounds().min().array() - tolerance, region.bounds().max().array() + tolerance));
  if (box.isEmpty()) return false;
  constexpr int samples = 17;
  for (int i = 0; i < samples; ++i)
    for (int j = 0; j < samples; ++j)
      for (int k = 0; k < samples; ++k) {
        const Eigen::Vector3d fraction(i, j, k);
        const Eigen::Vector3d x = box.min() + fraction.cwiseProduct(box.sizes()) / (samples - 1);
        if (shape.level_set(x) <= tolerance && region.contains(x, tolerance)) return true;
      }
  return false;
}

bool region_meets_points(const RegionSelector& region, const Eigen::MatrixXd& points, double tolerance) {
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (region.contains(points.row(i).transpose(), tolerance)) return true;
  return false;
}

// Methods mesh a shape at their own sizes; the surface they all deform is this one, fine
// enough that its own facets are not what a comparison measures. A box-built shape's
// planes are planes of its exact mesh's grid, so its features (a plate's thickness) are
// resolved at any size; sizing it by its smallest feature made a 1 m × 1 m × 1 mm plate
// a 48-million-cell mesh that never finished (issue #35).
SurfaceMesh shape_surface(const AnalyticShape& shape) {
  const double coarse = shape.bounding_box().diagonal().norm() / 40;
  const double size = shape.axis_planes() ? coarse : std::min(coarse, shape.smallest_feature() / 2);
  const VolumeMesh mesh =
      shape.axis_planes() ? tetrahedralize_box_shape(shape, size) : tetrahedralize_shape(shape, size, false);
  return boundary_surface(mesh).surface;
}

}  // namespace

SceneGeometry load_scene_geometry(const Scene& scene) {
  const GeometrySpec& spec = scene.geometry;
  const std::string file = scene.file.string();
  SceneGeometry geometry;
  geometry.scene_file = file;
  switch (spec.kind) {
    case GeometryKind::surface:
      geometry.surface = read_surface(spec.file, &geometry.warnings);
      transform(geometry.surface->vertices, spec.scale, spec.translate);
      geometry.bounds = bounds_of(geometry.surface->vertices);
      geometry.volume = surface_volume(*geometry.surface);
      break;
    case GeometryKind::mesh:
      geometry.mesh = read_volume_mesh(spec.file);
      transform(geometry.mesh->nodes, spec.scale, spec.translate);
      geometry.bounds = bounds_of(geometry.mesh->nodes);
      geometry.volume = cells_volume(*geometry.mesh);
      break;
    case GeometryKind::shape:
      geometry.shape = spec.scale == 1.0 && spec.translate.isZero(0.0)
                           ? spec.shape
                           : make_scaled_translated(spec.shape, spec.scale, spec.translate);
      geometry.bounds = geometry.shape->bounding_box();
      geometry.volume = geometry.shape->volume();
      geometry.shape_surface = shape_surface(*geometry.shape);
      break;
  }

  const double tolerance = region_tolerance(geometry.bounds);
  // Dirichlet and surface-load regions; a load region is checked against the loaded
  // surface's triangles again when a method is built (surface_traction.hpp).
  std::vector<const RegionSelector*> regions;
  for (const auto& condition : scene.dirichlet) regions.push_back(&condition.region);
  for (const auto& load : scene.tractions) regions.push_back(&load.region);
  for (const RegionSelector* selector : regions) {
    const RegionSelector& region = *selector;
    bool selects = false;
    std::string tested;
    if (geometry.surface) {
      selects = region_meets_points(region, geometry.surface->vertices, tolerance);
      tested = "no surface vertex among " + std::to_string(geometry.surface->vertices.rows());
    } else if (geometry.mesh) {
      selects = region_meets_points(region, geometry.mesh->nodes, tolerance);
      tested = "no mesh node among " + std::to_string(geometry.mesh->nodes.rows());
    } else {
      selects = region_meets_shape(region, *geometry.shape, tolerance);
      tested = "no point of the analytic shape";
    }
    if (!selects)
      throw InputError(
          input_message(file, region.pointer, "expected a region that selects part of the geometry, got " + tested));
  }
  return geometry;
}

}  // namespace altfem
