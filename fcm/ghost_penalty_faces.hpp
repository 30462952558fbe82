#pragma once
// The faces a ghost penalty acts on (Burman 2010; deal.II step-85's F_h): every face
// shared by two kept background cells at least one of which is cut, tabulated for
// FaceAssembler with both sides' values, gradients and (for quadratic cells) Hessians
// of the conforming Lagrange basis, so that GhostPenaltyKernel can form the jumps of
// the normal derivatives up to the cells' degree.
#include <vector>

#include "shared/assembly/tabulated_faces.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem::fcm {

struct GhostPenaltyFaces {
  TabulatedFaces faces;       ///< minus/plus: kept-cell indices; Hessians if the degree is 2
  std::vector<double> sizes;  ///< h_F per face: its longest edge (a hex face's side, as step-85's h)
};

/// The interior faces of `mesh` (the kept cells, basis function i = node i) next to a
/// cut cell, volume_fractions[c] < 1. Face rules of strength 2p on the reference face
/// (exact for the products of jumps on affine cells), points mapped into both
/// neighbours. Any cell geometry: Hessians include the map's curvature term. Throws
/// NumericalError when a face point cannot be located in the neighbour across it.
GhostPenaltyFaces ghost_penalty_faces(const VolumeMesh& mesh, const std::vector<double>& volume_fractions);

}  // namespace altfem::fcm
