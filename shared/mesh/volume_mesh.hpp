#pragma once
// A conforming volume mesh of one Lagrange element type, and its readers.
#include <Eigen/Core>
#include <filesystem>
#include <string_view>

#include "shared/element/element_type.hpp"

namespace altfem {

struct VolumeMesh {
  ElementType element_type = ElementType::tet4;
  Eigen::MatrixXd nodes;  ///< #nodes × 3
  Eigen::MatrixXi cells;  ///< #cells × nodes-per-cell, VTK node order, 0-based
};

/// Gmsh MSH 2.2 or 4.1 ASCII. Volume cells of one type (Tet4, Tet10, Hex8, Hex27);
/// lower-dimensional cells are ignored. Throws InputError naming file and line.
VolumeMesh parse_gmsh(std::string_view text, const std::string& file_name);
/// Medit .mesh (Tetrahedra, Hexahedra; Tet10 via TetrahedraP2). Throws InputError.
VolumeMesh parse_medit(std::string_view text, const std::string& file_name);
/// Reads a file by its extension (.msh, .mesh), then checks it with check_volume_mesh.
VolumeMesh read_volume_mesh(const std::filesystem::path& path);
/// Every node index in range, every node used, finite coordinates, no inverted or
/// zero-volume cell (the signed volume of each corner tetrahedron must be positive);
/// the error names the cell index.
void check_volume_mesh(const VolumeMesh& mesh, const std::string& file_name);

}  // namespace altfem
