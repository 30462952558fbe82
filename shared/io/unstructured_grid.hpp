#pragma once
// An in-memory VTK unstructured grid: what write_vtu writes.
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "shared/element/element_type.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// VTK cell types altfem writes besides those of element_vtk_cell_type.
inline constexpr int vtk_triangle = 5;
inline constexpr int vtk_polyhedron = 42;

/// Cells follow VTK's conventions (VTK file formats, "Unstructured grid"): node order
/// is VTK's, `offsets` holds each cell's *end* in `connectivity`, and a polyhedron
/// (VTK_POLYHEDRON) lists its distinct point ids in `connectivity` and its faces in
/// `polyhedron_faces`.
struct UnstructuredGrid {
  Eigen::MatrixXd points;             ///< #points × 3
  std::vector<int> cell_types;        ///< #cells, VTK cell type (10, 24, 71, 12, 25, 29, 5, 42, ...)
  std::vector<int64_t> connectivity;  ///< all cells' point ids, concatenated
  std::vector<int64_t> offsets;       ///< #cells, end of each cell in connectivity
  /// #cells or empty (no polyhedra); per cell its faces, each a list of point ids
  /// (ordered so the normal points outwards); empty for a cell that is not a polyhedron.
  std::vector<std::vector<std::vector<int64_t>>> polyhedron_faces;
  std::vector<std::pair<std::string, Eigen::MatrixXd>> point_data;  ///< name, #points × components
  std::vector<std::pair<std::string, Eigen::MatrixXd>> cell_data;   ///< name, #cells × components

  int64_t cell_count() const { return static_cast<int64_t>(cell_types.size()); }

  /// Appends one cell per row of `cells` (#cells × element_node_count(type), point
  /// ids in VTK node order). Throws std::invalid_argument on a wrong column count.
  void add_cells(ElementType type, const Eigen::MatrixXi& cells);
  /// Appends VTK_TRIANGLE cells; `triangles` is #triangles × 3.
  void add_triangles(const Eigen::MatrixXi& triangles);
  /// Appends one VTK_POLYHEDRON given by its faces (point ids, outward orientation);
  /// its connectivity is the faces' distinct point ids in order of first appearance.
  void add_polyhedron(const std::vector<std::vector<int64_t>>& faces);

private:
  void add_cell(int vtk_type, std::span<const int64_t> point_ids, std::vector<std::vector<int64_t>> faces = {});
};

/// The grid of a volume mesh: its nodes as points, its cells as one VTK cell type.
UnstructuredGrid grid_from_volume_mesh(const VolumeMesh& mesh);

}  // namespace altfem
