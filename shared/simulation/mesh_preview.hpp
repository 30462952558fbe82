#pragma once
// What `altfem mesh` shows of a method's mesh without solving: each method builds it as
// `run` would (app/mesh_command.cpp writes and prints it; a method registers its builder
// with its MethodDescription, so the command names no method).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "shared/io/unstructured_grid.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"

namespace altfem {

/// The command's choice of mesh source, for the methods that have several.
struct MeshPreviewOptions {
  /// "" (the mesh the method's block names), "convert" (the fem mesh, cell by cell) or
  /// "slice" (the geometry sliced by `slicing`).
  std::string source;
  SlicingOptions slicing;
};

struct MeshPreview {
  UnstructuredGrid grid;              ///< written as VTU
  nlohmann::json facts;               ///< printed with --json (and "method", "build_time_s", "file")
  std::string summary;                ///< the lines printed without --json
  std::vector<std::string> warnings;  ///< what the user should know, printed to stderr
};

}  // namespace altfem
