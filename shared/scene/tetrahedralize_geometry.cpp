#include "shared/scene/tetrahedralize_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "shared/common/error.hpp"
#include "shared/geometry/points_inside_surface.hpp"
#include "shared/mesh/mesh_components.hpp"
#include "shared/mesh/surface_projection.hpp"
#include "shared/mesh/tetrahedralize.hpp"

namespace altfem {

namespace {

// At most 2^21 voxels for counting a shape's pieces.
constexpr double max_voxels = 2097152.0;

Eigen::MatrixXd cell_centroids(const VolumeMesh& mesh) {
  Eigen::MatrixXd centroids = Eigen::MatrixXd::Zero(mesh.cells.rows(), 3);
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell)
    for (int corner = 0; corner < 4; ++corner) centroids.row(cell) += mesh.nodes.row(mesh.cells(cell, corner)) / 4.0;
  return centroids;
}

double tetrahedra_volume(const VolumeMesh& mesh) {
  double volume = 0;
  for (Eigen::Index cell = 0; cell < mesh.cells.rows(); ++cell) {
    const Eigen::Vector3d a = mesh.nodes.row(mesh.cells(cell, 0)), b = mesh.nodes.row(mesh.cells(cell, 1)),
                          c = mesh.nodes.row(mesh.cells(cell, 2)), d = mesh.nodes.row(mesh.cells(cell, 3));
    volume += (b - a).cross(c - a).dot(d - a) / 6.0;
  }
  return volume;
}

// How far each centroid lies outside the geometry (0 inside).
std::vector<double> outside_distances(const SceneGeometry& geometry, const Eigen::MatrixXd& centroids) {
  std::vector<double> distances(static_cast<std::size_t>(centroids.rows()), 0.0);
  if (geometry.shape) {
    for (Eigen::Index i = 0; i < centroids.rows(); ++i)
      distances[i] = std::max(0.0, geometry.shape->level_set(centroids.row(i).transpose()));
    return distances;
  }
  const std::vector<SurfaceSide> sides =
      points_inside_surface(geometry.surface->vertices, geometry.surface->triangles, centroids);
  const SurfaceProjection projection(*geometry.surface);
  for (Eigen::Index i = 0; i < centroids.rows(); ++i)
    if (sides[i] == SurfaceSide::outside)
      distances[i] = (projection.closest_point(centroids.row(i).transpose()) - centroids.row(i).transpose()).norm();
  return distances;
}

std::string number(double value) {
  std::ostringstream text;
  text.precision(3);
  text << value;
  return text.str();
}

}  // namespace

VolumeMesh tetrahedralize_geometry(const SceneGeometry& geometry, double max_cell_size, const std::string& size_key) {
  const auto fail = [&](const std::string& what) {
    throw InputError(input_message(geometry.scene_file, size_key, what));
  };
  if (geometry.shape && geometry.shape->axis_planes()) return tetrahedralize_box_shape(*geometry.shape, max_cell_size);

  const double size = geometry.shape ? std::min(max_cell_size, geometry.shape->smallest_feature()) : max_cell_size;
  const VolumeMesh mesh = geometry.shape ? tetrahedralize_shape(*geometry.shape, max_cell_size)
                                         : tetrahedralize_surface(*geometry.surface, max_cell_size);

  const int pieces = volume_mesh_components(mesh);
  if (geometry.surface) {
    const int solids = surface_solid_components(*geometry.surface);
    if (pieces != solids)
      fail("the tetrahedral mesh has " + std::to_string(pieces) + " connected piece(s) where the surface bounds " +
           std::to_string(solids) + " (cells bridge a gap or cut a part thinner than the cell size " + number(size) +
           "); expected a smaller value");
  } else {
    const Eigen::AlignedBox3d box = geometry.shape->bounding_box();
    const double spacing = std::max(size / 4, std::cbrt(box.volume() / max_voxels));
    const int solids = shape_components(*geometry.shape, spacing);
    if (pieces < solids)
      fail("the tetrahedral mesh has " + std::to_string(pieces) + " connected piece(s) where the shape has " +
           std::to_string(solids) + " (cells bridge a gap narrower than the cell size " + number(size) +
           "); expected a value below the gap");
  }

  const double facet_distance = size / 10;
  const std::vector<double> distances = outside_distances(geometry, cell_centroids(mesh));
  const auto worst = std::max_element(distances.begin(), distances.end());
  if (worst != distances.end() && *worst > facet_distance)
    fail("cell " + std::to_string(worst - distances.begin()) + "'s centroid lies " + number(*worst) +
         " outside the geometry (more than the facet distance " + number(facet_distance) +
         ": cells span a gap or a concave part); expected a smaller value than " + number(max_cell_size));

  const double volume = tetrahedra_volume(mesh);
  const double error = std::abs(volume - geometry.volume) / geometry.volume;
  if (error > tetrahedralization_volume_tolerance)
    fail("the tetrahedral mesh's volume " + number(volume) + " differs from the geometry's " + number(geometry.volume) +
         " by " + number(100 * error) + "% (more than " + number(100 * tetrahedralization_volume_tolerance) +
         "%); expected a smaller value than " + number(max_cell_size));
  return mesh;
}

}  // namespace altfem
