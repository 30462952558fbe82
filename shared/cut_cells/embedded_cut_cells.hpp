#pragma once
// The cells of a Lagrange mesh with the material of an embedded tetrahedral mesh in them
// (Longva et al. 2020): their connected pieces of material with node copies (cell_pieces,
// piece_mesh), their cut-cell rules (intersection_cell_quadrature), the stabilised
// discretization (build_fcm_discretization), and what events need of them: a cut of the
// embedded tetrahedra, and which node each node copy continues. fcm builds them on its
// background grid; fem on its own mesh after a cut — the virtual node algorithm (Molino
// et al. 2004) at any Lagrange order: a cut element keeps its nodes, gets one copy of them
// per piece of material, and integrates each copy over its piece.
#include <Eigen/Core>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "shared/cut_cells/cell_pieces.hpp"
#include "shared/cut_cells/fcm_discretization.hpp"
#include "shared/cut_cells/intersection_cell_quadrature.hpp"
#include "shared/cut_cells/piece_mesh.hpp"
#include "shared/io/unstructured_grid.hpp"
#include "shared/mesh/cell_face_contact.hpp"
#include "shared/mesh/cut_tetrahedral_mesh.hpp"
#include "shared/mesh/cutting_plane.hpp"
#include "shared/simulation/basis_embedding.hpp"
#include "shared/simulation/scene_materials.hpp"

namespace altfem {

/// How the cells are cut and integrated (fcm: its scene block's; fem: exact, kept, unstabilised).
struct CutCellSettings {
  FcmOptions options;
  std::optional<SimplificationMethod> simplifier = SimplificationMethod::caratheodory;  ///< nullopt: none
  double simplification_tolerance = 1e-12;
  /// One copy of a cell's nodes per connected piece of material in it (piece_mesh.hpp).
  bool topology_aware = true;
};

/// The material: Tet4 cells conforming by node in the convex fragments they fill
/// (cut_tetrahedral_mesh.hpp), and per fragment the fragment of the material before the
/// last cut that it lies in (empty: not cut, the fragments are their own).
struct EmbeddedTetrahedra {
  FragmentedTetrahedra material;
  std::vector<int> parent;

  const VolumeMesh& mesh() const { return material.mesh; }
};

/// A background grid refined 1→8 (hexahedral_forest.hpp): its nodes from `free_nodes` on
/// hang, from `sources`; `contacts`: which cells touch across its faces (a coarse face
/// touches finer ones).
struct RefinedBackground {
  int free_nodes = 0;
  HangingNodeSources sources;
  std::vector<CellFaceContact> contacts;
};

/// What a rebuild after an event hands on (both optional).
struct CutCellRebuild {
  /// The background's hanging nodes, constrained among the kept cells
  /// (build_fcm_discretization); the background's nodes then hold them last.
  const RefinedBackground* refined = nullptr;
  /// The cell rules built before (rule_memory()): a cell the event left alone (the same
  /// corners, the same tetrahedra) takes its rules from there instead of being integrated again.
  std::shared_ptr<const CellRuleMemory> rules;
  /// The tetrahedra's clips by the cells built before (clip_memory()): one the event left
  /// alone in a cell the same is not clipped again (find_cell_pieces).
  std::shared_ptr<const ClippedTetrahedronMemory> clips;
  /// Whether to keep this build's clips for the next (a scene whose events rebuild).
  bool remember_clips = false;
};

class EmbeddedCutCells {
public:
  EmbeddedCutCells(const VolumeMesh& background, EmbeddedTetrahedra embedded, const CutCellSettings& settings,
                   const SceneMaterials& materials, const std::vector<DirichletCondition>& dirichlet,
                   const std::string& scene_file, const CutCellRebuild& rebuild = {});

  /// The kept cells (a cell per piece of material), nodes renumbered: basis function i =
  /// node i, hanging nodes last (FcmDiscretization::constraints).
  const FcmDiscretization& discretization() const { return fcm_; }
  const VolumeMesh& background() const { return background_; }
  const EmbeddedTetrahedra& embedded() const { return embedded_; }
  int quadrature_strength() const { return settings_.options.quadrature_strength; }
  /// Seconds spent finding the pieces, generating the rules and building the discretization.
  double seconds() const { return seconds_; }
  /// Σ vol(K ∩ Ω) over the kept cells: the material's volume, without the fictitious parts
  /// that the stabilisation weighs by α (§5.3).
  double material_volume() const { return material_volume_; }
  /// Dirichlet regions that cut through cells (conditions_cutting_cells).
  const std::vector<std::string>& warnings() const { return warnings_; }
  /// The kept cells' basis at any point: a point in a cell of several pieces takes the
  /// nearest piece's copy (PieceBasisEvaluator).
  std::unique_ptr<ElementBasisEvaluator> basis_evaluator() const;
  /// The kept cells with "volume_fraction", "quadrature_points" and "piece" cell data.
  UnstructuredGrid volume_grid(const Eigen::VectorXd& displacement) const;
  /// {"cells": {inside, cut, discarded, split, outside}, "cut_cell_points", …}.
  nlohmann::json facts() const;

  /// Every cell's rules of this build, by key, for the next rebuild (CutCellRebuild::rules).
  std::shared_ptr<const CellRuleMemory> rule_memory() const { return rule_memory_; }
  /// This build's clips of the tetrahedra by the cells (null unless remember_clips).
  std::shared_ptr<const ClippedTetrahedronMemory> clip_memory() const { return clip_memory_; }
  /// Per kept cell, the background cell it is (or is a piece of).
  std::vector<int> background_cell_of_kept() const;

  /// Why these cells cannot be cut (one phrase); empty when they can.
  std::string cut_refusal() const;
  /// The embedded tetrahedra cut by `blade` (cut_tetrahedral_mesh); `facts` receives its counts.
  EmbeddedTetrahedra cut(const CuttingPlane& blade, nlohmann::json& facts) const;
  /// Nodal fields of `before` (#free kept nodes of before · 3 × #fields; `before_basis` its
  /// basis) on these free kept nodes: a node copy takes the values of the copy it continues
  /// (node_origins) bit for bit; only where some node continues none (another
  /// background, a piece that was not kept) or nodes hang are the old fields evaluated at
  /// the nodes (transfer_to_nodes): exactly, where the spaces are nested (a refinement).
  Eigen::MatrixXd transfer(const EmbeddedCutCells& before, const ElementBasisEvaluator& before_basis,
                           const Eigen::MatrixXd& fields) const;
  /// Nodal fields of the background mesh's own nodes (#background nodes · 3 × #fields:
  /// fem before its first cut) on these kept nodes: each copy takes its node's values.
  Eigen::MatrixXd transfer_from_background(const Eigen::MatrixXd& fields) const;

private:
  bool continues(const EmbeddedCutCells& before) const;
  /// Per kept node, the kept node of `before` whose values it continues: a kept cell's
  /// tetrahedra lie in one piece of the same background cell before, whose kept cell has
  /// the node at the same corner; −1 where that piece was not kept. Empty when this was
  /// not built on `before`'s background and embedded tetrahedra, or a cut of them.
  std::vector<int> node_origins(const EmbeddedCutCells& before) const;
  /// Per kept node, the background node it is a copy of.
  std::vector<int> background_nodes() const;

  CutCellSettings settings_;
  VolumeMesh background_;  ///< before topology-aware splitting
  EmbeddedTetrahedra embedded_;
  std::optional<PieceMesh> pieces_;  ///< topology-aware cells only
  int split_cells_ = 0;
  double topology_seconds_ = 0, seconds_ = 0, material_volume_ = 0;
  std::shared_ptr<IntersectionStatistics> statistics_;
  std::shared_ptr<CellRuleMemory> rule_memory_;
  std::shared_ptr<ClippedTetrahedronMemory> clip_memory_;
  FcmDiscretization fcm_;
  std::vector<std::string> warnings_;
};

/// `material` cut by `blade` (cut_tetrahedral_mesh); `facts` receives its counts.
EmbeddedTetrahedra cut_embedded_tetrahedra(const FragmentedTetrahedra& material, const CuttingPlane& blade,
                                           nlohmann::json& facts);

}  // namespace altfem
