#pragma once
// The `fcm` block of a scene (docs/scene-schema.md, "fcm"): the background grid, the
// embedded mesh, the cut-cell quadrature and the conditioning remedies of Longva et
// al. 2020, with the authors' defaults.
#include <Eigen/Geometry>
#include <filesystem>
#include <optional>

#include "shared/cut_cells/fcm_discretization.hpp"
#include "shared/element/element_type.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/quadrature/simplify_quadrature.hpp"
#include "shared/scene/method_scene_block.hpp"

namespace altfem::fcm {

struct FcmSpec {
  ElementType cell = ElementType::hex20;
  /// Cells per axis over the background box; nullopt: default_grid_resolution of the
  /// box, known once the geometry is loaded.
  std::optional<Eigen::Vector3i> resolution;
  /// Edge of cubic cells instead of `resolution`: whole cells from the box's lower corner.
  std::optional<double> cell_size;
  /// A user-supplied background mesh (world coordinates) instead of the generated grid.
  std::optional<std::filesystem::path> background;
  /// The background box is the geometry's bounds grown by this fraction of their extent
  /// on every side. 0 puts the grid's outer planes on the bounds, where the shipped
  /// scenes put their Dirichlet regions (§6: conditions act on background nodes).
  double margin = 0.0;
  /// Mesh_3 cell size of the embedded tetrahedral mesh of a surface or shape; nullopt:
  /// the bounds' diagonal / 15, as fem's default (the two then deform the same surface).
  std::optional<double> embedded_cell_size;
  std::optional<SimplificationMethod> simplifier = SimplificationMethod::caratheodory;  ///< nullopt: none
  double simplification_tolerance = 1e-12;
  /// One copy of a cell's DOFs per connected piece of material in it (piece_mesh.hpp):
  /// disconnected parts sharing a cell move independently (the limitation of §7).
  bool topology_aware = true;
  FcmOptions options;  ///< strengths, discarding, stabilisation, Schwarz
};

const MethodSceneBlock& fcm_scene_block();

/// The resolved /discretization/fcm of `scene`. Throws InputError for a bad block.
FcmSpec fcm_spec(const Scene& scene);

/// The background grid's box: `bounds` grown by `margin` × their extent on every side.
Eigen::AlignedBox3d background_box(const Eigen::AlignedBox3d& bounds, double margin);

struct BackgroundMesh {
  VolumeMesh mesh;
  std::optional<Eigen::Vector3i> resolution;  ///< cells per axis of a generated grid
};

/// The background cells of §3.2: the spec's mesh file, else a structured grid of
/// `spec.cell` over background_box(bounds, margin) at `resolution`, `cell_size`, or
/// default_grid_resolution. Throws InputError for an unreadable file.
BackgroundMesh background_mesh(const FcmSpec& spec, const Eigen::AlignedBox3d& bounds);

}  // namespace altfem::fcm
