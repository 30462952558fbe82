#pragma once
// The FCM's face ghost penalty (Burman 2010; deal.II step-85's F_h and g_F): every
// face shared by two kept background cells at least one of which is cut, tabulated for
// FaceAssembler with both sides' values, gradients and (for quadratic cells) Hessians
// of the conforming Lagrange basis, and the energy term GhostPenaltyKernel makes of
// them with the jumps of the normal derivatives up to the cells' degree.
#include <memory>
#include <vector>

#include "shared/assembly/energy_term.hpp"
#include "shared/assembly/tabulated_faces.hpp"
#include "shared/material/material.hpp"
#include "shared/mesh/node_constraints.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

struct GhostPenaltyFaces {
  TabulatedFaces faces;       ///< minus/plus: kept-cell indices; Hessians if the degree is 2
  std::vector<double> sizes;  ///< h_F per face: its longest edge (a hex face's side, as step-85's h)
};

/// The interior faces of `mesh` (the kept cells, basis function i = node i) next to a
/// cut cell, volume_fractions[c] < 1. Face rules of strength 2p on the reference face
/// (exact for the products of jumps on affine cells), points mapped into both
/// neighbours. Any cell geometry: Hessians include the map's curvature term. Tabulates the
/// faces f with here(f), every face when `here` is empty, and lists the others
/// (TabulatedFaces::add_held_elsewhere); `sizes` are every face's. Throws NumericalError when
/// a face point cannot be located in the neighbour across it.
///
/// With hanging nodes (`constraints`, a refined grid's: nodes past free_nodes), a finer
/// cell's face on a coarser cell's face is a face too — its rule on the finer face, h_F its
/// longest edge, the finer cell its minus side — and the faces' functions are the free
/// nodes', each hanging node's traces added to its masters' with the constraint's weights.
GhostPenaltyFaces ghost_penalty_faces(const VolumeMesh& mesh, const std::vector<double>& volume_fractions,
                                      const TabulatedHere& here = nullptr,
                                      const NodeConstraints* constraints = nullptr);

/// The penalty's energy term over `faces` on cells of `type`: γ_F = γ × the mean P-wave
/// modulus λ + 2μ of the face's two cells, so that the penalty scales like the elastic
/// stiffness it stabilises and γ is dimensionless. cell_materials: per cell of the faces'
/// mesh, its index into `materials`. Without `tabulate`, `faces` are tabulated and must
/// outlive the term; with it, `faces` need only list them, and the term tabulates its
/// share when it learns it (FaceAssembler's FaceTabulator: over several ranks each rank
/// tabulates the faces it owns).
std::unique_ptr<EnergyTerm> ghost_penalty_term(const GhostPenaltyFaces& faces, ElementType type,
                                               const std::vector<int>& cell_materials,
                                               const std::vector<const Material*>& materials, double gamma,
                                               FaceTabulator tabulate = nullptr);

}  // namespace altfem
