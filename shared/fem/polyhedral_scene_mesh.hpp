#pragma once
// The polyhedral mesh a polyhedral method (dg, harmonic) runs on, from either source its
// scene block names: a tet or hex mesh built by the fem rules and converted cell by cell,
// or the geometry sliced by a grid (Kaufmann et al. 2009, §9.2; Martin et al. 2008, §7).
#include <nlohmann/json.hpp>
#include <optional>

#include "shared/fem/fem_scene_block.hpp"
#include "shared/geometry/polyhedron.hpp"
#include "shared/mesh/cut_polyhedral_mesh.hpp"
#include "shared/mesh/slice_into_polyhedra.hpp"
#include "shared/mesh/surface_mesh.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/scene/scene_geometry.hpp"

namespace altfem {

struct PolyhedralMeshSource {
  std::optional<SlicingOptions> slicing;  ///< set: hexahedral slicing; unset: conversion of `convert`
  FemSpec convert;                        ///< the volume mesh converted (resolved fem rules)
};

/// A piece of a cell before a cut, merged with pieces of other cells into one cell.
struct ParentPart {
  int parent = -1;  ///< the cell before that holds it
  Polyhedron piece;
};

struct PolyhedralSceneMesh {
  /// The mesh, and when sliced the slicing's counts (all zero for a converted mesh).
  SlicedMesh sliced;
  /// The surface the method deforms when the geometry has none in common
  /// (SceneGeometry::common_surface): the boundary of the volume mesh (the converted one,
  /// or the scene's own when sliced). Empty otherwise: the method deforms the geometry's,
  /// which Simulation cuts with the body, so that a cut does not cut it twice.
  SurfaceMesh surface;
  /// The surface loads act on: the boundary of the domain integrated, as triangles each
  /// on one cell's face (the converted volume mesh's boundary; the sliced mesh's boundary
  /// faces, ear-clipped).
  SurfaceMesh load_surface;
  /// {"source": "convert" | "slice"} and, when sliced, "slicing": slicing_facts.
  nlohmann::json facts;
  /// The tet or hex mesh that was converted (its conforming basis serves dg's stitched
  /// embedding); unset when sliced.
  std::optional<VolumeMesh> converted;
  /// After a cut: per node, the nodes of the mesh before it that it comes from (nodal
  /// methods carry their fields through these); empty otherwise.
  std::vector<NodeSource> node_sources;
  /// After a cut or a refinement: per cell, the cell of the mesh before that holds it whole
  /// (-1 for a cell merged from pieces of several); empty otherwise. Methods whose basis is
  /// per cell carry a field through these exactly (dg re-expands the parent's polynomial).
  std::vector<int> parent_cells;
  /// After a cut that merged pieces of several cells into one (parent_cells −1): per cell,
  /// those pieces, for such a cell, but for flat pieces of rounding size (no volume, faces
  /// that may not close); empty for every other cell (empty altogether when none).
  /// dg projects its field on such a cell piece by piece, each with its parent's polynomial.
  std::vector<std::vector<ParentPart>> merged_parts;
  /// Per cell, how many refinements split the cells it lies in (refine events' max_level);
  /// empty: none.
  std::vector<int> cell_levels;
};

/// What a polyhedral method was built on, as an event hands it on: `mesh`, the surface it
/// deforms when that is its own (null: the geometry's common one), the load surface, the
/// facts and the cells' levels; no converted mesh (the caller sets it where it keeps one)
/// and no node sources or parent cells.
PolyhedralSceneMesh handed_polyhedral_scene_mesh(const PolyhedralMesh& mesh, const SurfaceMesh* own_surface,
                                                 const SurfaceMesh& load_surface, const nlohmann::json& facts,
                                                 const std::vector<int>& cell_levels);

/// The boundary faces of a polyhedral mesh as outward triangles over the nodes they use
/// (ear-clipped): the surface loads act on.
SurfaceMesh boundary_faces_surface(const PolyhedralMesh& mesh);

/// The surface a method on `mesh` deforms: `mesh.surface`, or the geometry's common surface
/// when that is empty.
const SurfaceMesh& deformed_surface(const PolyhedralSceneMesh& mesh, const SceneGeometry& geometry);

/// Builds the mesh `source` describes for the scene's geometry. Throws InputError and
/// NumericalError as build_fem_mesh and slice_scene_geometry do.
PolyhedralSceneMesh build_polyhedral_scene_mesh(const PolyhedralMeshSource& source, const SceneGeometry& geometry);

}  // namespace altfem
