// CGAL's Hilbert sort rather than our own space-filling curve: it adapts the
// curve's subdivision to the point distribution (median policy), so graded meshes
// stay local too.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <numeric>
#include <vector>

#include "shared/mesh/spatial_order.hpp"

namespace altfem {

VolumeMesh spatially_ordered(const VolumeMesh& mesh) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Kernel::Point_3;
  const Eigen::Index cell_count = mesh.cells.rows();
  const Eigen::Index nodes_per_cell = mesh.cells.cols();

  std::vector<Point> centroids;
  centroids.reserve(static_cast<std::size_t>(cell_count));
  for (Eigen::Index cell = 0; cell < cell_count; ++cell) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (Eigen::Index k = 0; k < nodes_per_cell; ++k) centroid += mesh.nodes.row(mesh.cells(cell, k)).transpose();
    centroid /= static_cast<double>(nodes_per_cell);
    centroids.emplace_back(centroid.x(), centroid.y(), centroid.z());
  }
  std::vector<std::size_t> cell_order(static_cast<std::size_t>(cell_count));
  std::iota(cell_order.begin(), cell_order.end(), 0);
  using Traits = CGAL::Spatial_sort_traits_adapter_3<Kernel, CGAL::Pointer_property_map<Point>::type>;
  CGAL::hilbert_sort(cell_order.begin(), cell_order.end(), Traits(CGAL::make_property_map(centroids)));

  const Eigen::Index node_count = mesh.nodes.rows();
  std::vector<int> new_index(static_cast<std::size_t>(node_count), -1);
  int next = 0;
  VolumeMesh ordered;
  ordered.element_type = mesh.element_type;
  ordered.cells.resize(cell_count, nodes_per_cell);
  for (Eigen::Index position = 0; position < cell_count; ++position)
    for (Eigen::Index k = 0; k < nodes_per_cell; ++k) {
      int& index = new_index[static_cast<std::size_t>(
          mesh.cells(static_cast<Eigen::Index>(cell_order[static_cast<std::size_t>(position)]), k))];
      if (index < 0) index = next++;
      ordered.cells(position, k) = index;
    }
  for (int& index : new_index)
    if (index < 0) index = next++;
  ordered.nodes.resize(node_count, 3);
  for (Eigen::Index node = 0; node < node_count; ++node)
    ordered.nodes.row(new_index[static_cast<std::size_t>(node)]) = mesh.nodes.row(node);
  return ordered;
}

}  // namespace altfem
