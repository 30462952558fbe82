#pragma once
// fem after a cut (issue #33): the virtual node algorithm (Molino et al. 2004) at any
// Lagrange order. The blade cuts the elements' own material (element_material: their
// corner tetrahedra, a grid's hexahedra whole); each element becomes one cell per piece of
// material in it, with its own copy of the element's nodes, integrated over its piece by
// cut-cell rules (shared/cut_cells: fcm's cells with the fem mesh as the background, kept
// whole and unstabilised); an element the blade does not reach keeps its standard rule.
#include <memory>
#include <optional>

#include "shared/cut_cells/embedded_cut_cells.hpp"
#include "shared/mesh/hexahedral_forest.hpp"
#include "shared/simulation/method_instance.hpp"

namespace altfem {

/// What fem is built on: its elements, and once cut, the material as their cut tetrahedra;
/// on a hexahedral grid the forest a refine event splits, and its hanging nodes (the last
/// nodes of `elements`); once cut again, the cut-cell rules of the build before, which the
/// cells the cut left alone take (CutCellRebuild::rules).
struct FemMesh {
  VolumeMesh elements;
  std::optional<EmbeddedTetrahedra> material;
  std::optional<HexahedralForest> forest;
  NodeConstraints constraints;
  std::shared_ptr<const CellRuleMemory> rules;
};

/// The elements' material as tetrahedra (uncut), conforming by node as the elements are,
/// what the first cut cuts: Tet4/Tet10 corners; convex hexahedra (a grid's) as fragments of
/// 6 (convex_cells_as_fragments), which a cut cuts whole; other hexahedra 12 about their
/// centroid (tetrahedra_of_hexahedra).
FragmentedTetrahedra element_material(const VolumeMesh& elements);

/// Why fem cannot cut a mesh of this element type (one phrase); empty when it can.
std::string fem_cut_refusal(ElementType type);

/// The failure hint (MethodInstance::failure_hint) of fem in a scene that cuts: without
/// `cut_stabilization` a piece of a vanishing fraction of its element leaves its functions
/// almost no mass or stiffness; empty when the cut pieces are stabilised.
std::string fem_cut_failure_hint(double cut_stabilization);

/// fem on `mesh.elements` cut into `*mesh.material`.
std::unique_ptr<MethodInstance> make_cut_fem_method(const Scene& scene, const SceneGeometry& geometry,
                                                    const FemMesh& mesh);

}  // namespace altfem
