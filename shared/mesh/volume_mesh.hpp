#pragma once
// A conforming volume mesh of one Lagrange element type, and its readers.
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <string_view>

#include "shared/element/element_type.hpp"

namespace altfem {

struct VolumeMesh {
  ElementType element_type = ElementType::tet4;
  Eigen::MatrixXd nodes;  ///< #nodes × 3
  Eigen::MatrixXi cells;  ///< #cells × nodes-per-cell, VTK node order, 0-based
};

/// Gmsh MSH 2.2 or 4.1 ASCII text. Volume cells of one type (Tet4, Tet10, Hex8, Hex20,
/// Hex27), permuted from Gmsh's node order to VTK's; lower-dimensional cells and the
/// nodes only they use are dropped. Throws InputError "file: line N: what".
VolumeMesh parse_gmsh(std::string_view text, const std::string& file_name);
/// Medit .mesh ASCII text (Tetrahedra or Hexahedra; lower-dimensional sections are
/// skipped; TetrahedraP2 is refused: its node order is not documented). Throws
/// InputError "file: line N: what".
VolumeMesh parse_medit(std::string_view text, const std::string& file_name);
/// Reads a file by its extension (.msh, .mesh), then checks it with check_volume_mesh.
/// A missing, empty or directory path is an InputError too.
VolumeMesh read_volume_mesh(const std::filesystem::path& path);
/// Every node index in range, every node used, finite coordinates, no inverted or
/// zero-volume cell (the signed volume of each corner tetrahedron must be positive);
/// the error names the cell index.
void check_volume_mesh(const VolumeMesh& mesh, const std::string& file_name);

/// Sum of the cells' volumes from their corners: exact for straight-sided cells
/// (a tetrahedron's corner tetrahedron; a hexahedron's trilinear map).
double volume_mesh_volume(const VolumeMesh& mesh);
/// The mean of each cell's corner nodes (#cells × 3).
Eigen::MatrixX3d corner_centroids(const VolumeMesh& mesh);

}  // namespace altfem
