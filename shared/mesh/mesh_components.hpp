#pragma once
// Connected pieces of meshes and shapes: what `tetrahedralize_geometry` compares so that
// a mesh never glues together parts that the geometry keeps apart (#21 item 5).
#include <vector>

#include "shared/geometry/analytic_shape.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// Pieces of a tetrahedral mesh (any order; its corner tetrahedra count) connected
/// through shared faces: two cells that meet only at an edge or a node are apart.
int volume_mesh_components(const VolumeMesh& mesh);

/// Pieces of a polyhedral mesh connected through interior faces (face_cells with two cells).
int polyhedral_mesh_components(const PolyhedralMesh& mesh);

/// Solid pieces bounded by a closed, outward-oriented surface: its shells (triangles
/// joined through edges) that enclose positive volume; a cavity's inward shell is not one.
int surface_solid_components(const SurfaceMesh& surface);

/// Per vertex of `surface`, the piece of it the vertex lies in: triangles joined through
/// shared vertices, each piece numbered by its lowest vertex. A vertex no triangle uses is
/// its own piece.
std::vector<int> surface_vertex_pieces(const SurfaceMesh& surface);

/// Pieces of {level_set < 0} on a voxel grid of the shape's bounding box with at most
/// `spacing` between samples (face-connected voxels whose centres are inside). Parts
/// closer together than the spacing count as one.
int shape_components(const AnalyticShape& shape, double spacing);

}  // namespace altfem
