#pragma once
// VTK XML unstructured grid (.vtu) output.
#include <filesystem>
#include <string>

#include "shared/io/unstructured_grid.hpp"

namespace altfem {

/// The .vtu text of `grid`: VTK XML format version 1.0, binary appended data with raw
/// encoding, UInt64 size headers, little-endian; Float64 points and data, Int64
/// connectivity/offsets/faces/faceoffsets, UInt8 types. Polyhedra use the `faces` +
/// `faceoffsets` arrays (faceoffsets −1 for other cells); `faces` carries no
/// NumberOfComponents attribute, which meshio 5 requires to read it.
/// Throws std::invalid_argument naming `file_name` for an inconsistent grid (array
/// sizes, point ids out of range, wrong node count for a fixed-size cell type) and
/// NumericalError naming the array and row for a non-finite value.
std::string vtu_text(const UnstructuredGrid& grid, const std::string& file_name);

/// Writes vtu_text(grid) to `path` atomically (write_file_atomically).
void write_vtu(const std::filesystem::path& path, const UnstructuredGrid& grid);

}  // namespace altfem
