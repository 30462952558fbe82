#pragma once
// The finite cell discretization (Longva et al. 2020 §3.2-5): the conforming Lagrange
// parts of shared/fem on the background cells that hold material, with the cut cells'
// own rules for stiffness and (at a higher strength, never simplified) mass, small cut
// cells discarded, the quadrature stabilised, the Additive-Schwarz preconditioner
// over the small cut cells, and (a remedy the paper does not use) a face ghost penalty.
#include <memory>
#include <string>
#include <vector>

#include "shared/assembly/tabulated_discretization.hpp"
#include "shared/cut_cells/cell_quadrature.hpp"
#include "shared/cut_cells/ghost_penalty_faces.hpp"
#include "shared/fem/nodal_dirichlet.hpp"
#include "shared/mesh/hexahedral_forest.hpp"
#include "shared/mesh/node_constraints.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/scene/scene.hpp"

namespace altfem {

/// Which matrices get the stabilising points (§5.3).
enum class StabilizedMatrices { none, mass, mass_and_stiffness };

struct FcmOptions {
  int quadrature_strength = 4;       ///< stiffness rules (the paper: Hex20 4, Tet10 3, Hex8 2)
  int mass_quadrature_strength = 8;  ///< mass and load rules (higher, never simplified; §6)
  /// Cells whose volume fraction is below this are discarded (§5.3; 0: keep all, the
  /// default: the stabilisation keeps the smallest cells' matrices definite, and a
  /// discarded cell's share of a surface load reaches the nodes of its kept neighbours
  /// through their bases extrapolated, docs/performance.md, "Discarding cut cells").
  double discard_fraction = 0;
  /// §5.3: every cut cell also gets the uncut cell's standard points with weights
  /// scaled by this factor (0: off). They are added to the final (simplified) rule, so
  /// that simplification never trades them against the material's points.
  double stabilization = 1e-6;
  StabilizedMatrices stabilized = StabilizedMatrices::mass_and_stiffness;
  /// §5.2: cut cells below this volume fraction get an Additive-Schwarz block.
  double schwarz_fraction = 0.5;
  double schwarz_epsilon = 1e-13;  ///< ε of eq. (14)
  /// γ of the face ghost penalty on the faces of cut cells (Burman 2010, in deal.II
  /// step-85's form; GhostPenaltyKernel), scaled by the P-wave modulus λ + 2μ so that it
  /// is dimensionless (0: off). Another remedy for small cuts than §5.2-5.3's.
  double ghost_penalty = 0;
};

struct FcmCellCounts {
  int inside = 0, cut = 0, discarded = 0, outside = 0;
};

/// Hanging nodes of a refined background grid (hexahedral_forest.hpp): the grid's nodes from
/// `grid_free_nodes` on hang, from `sources`; per node and per cell of the mesh
/// build_fcm_discretization is handed, the grid node and cell it copies or is a piece of
/// (piece_mesh's background_node and background_cell; empty: that mesh is the grid).
struct BackgroundHangingNodes {
  const HangingNodeSources* sources = nullptr;  ///< null: none hangs
  int grid_free_nodes = 0;
  std::vector<int> grid_node, grid_cell;
};

struct FcmDiscretization {
  /// The kept cells, nodes renumbered: basis function i = node i for the free nodes, the
  /// hanging ones last (`constraints`).
  VolumeMesh mesh;
  NodeConstraints constraints;           ///< free_nodes: every node when none hangs
  std::vector<int> background_cells;     ///< per kept cell: its index in the background grid
  std::vector<double> volume_fractions;  ///< per kept cell
  FcmCellCounts counts;
  int schwarz_blocks = 0;
  /// The ghost penalty's faces, listed (null when off): the face term tabulates those it
  /// assembles, every face on one process, its own over several ranks.
  std::unique_ptr<GhostPenaltyFaces> ghost;
  std::unique_ptr<TabulatedDiscretization> discretization;
};

/// Builds the FCM on `background` (any Lagrange grid) for `material` (which must
/// outlive the result) with nodal Dirichlet conditions on the kept nodes. Throws
/// InputError when no cell holds material or a condition selects no kept node.
FcmDiscretization build_fcm_discretization(const VolumeMesh& background, const CellQuadratureSource& quadrature,
                                           const Material& material, const std::vector<DirichletCondition>& dirichlet,
                                           const FcmOptions& options, const std::string& scene_file = "scene");
/// The same with several materials: background_materials holds each background cell's
/// index into `materials` (a cut cell takes one material whole). `dirichlet_nodes`
/// (nodes of `background`; optional) narrows the nodes each region selects
/// (topology-aware cells: piece_dirichlet.hpp). With `hanging`, the kept hanging nodes are
/// constrained to their masters' kept copies (kept_hanging_nodes): the tabulation, the
/// element masses, the Schwarz blocks and the Dirichlet conditions see the free nodes only.
/// The ghost penalty is refused there (std::invalid_argument): its face terms do not take
/// constraints.
FcmDiscretization build_fcm_discretization(const VolumeMesh& background, const CellQuadratureSource& quadrature,
                                           std::vector<const Material*> materials,
                                           const std::vector<int>& background_materials,
                                           const std::vector<DirichletCondition>& dirichlet, const FcmOptions& options,
                                           const std::string& scene_file = "scene",
                                           const NodeRegionFilter& dirichlet_nodes = {},
                                           const BackgroundHangingNodes& hanging = {});

}  // namespace altfem
