#pragma once
#include "shared/mesh/boundary_surface.hpp"
#include "shared/mesh/volume_mesh.hpp"
#include "shared/simulation/surface_lift.hpp"

namespace altfem {

/// The isoparametric boundary faces of a Lagrange mesh, for the triangles of
/// boundary_surface(mesh): triangle t lies on a face of its cell, its corners at the
/// reference points ξ_0, ξ_1, ξ_2 of three corner nodes, so barycentric λ maps to
/// x(Σ λ_i ξ_i) of the cell's geometry map, with area vector (J (ξ_1 − ξ_0)) × (J (ξ_2 − ξ_0)).
/// Curved Tet10, Tet20, Hex20 and Hex27 faces are integrated exactly so; on straight
/// cells the lift is the triangle itself. Keeps copies of what it needs.
SurfaceLift lagrange_surface_lift(const VolumeMesh& mesh, const BoundarySurface& boundary);

}  // namespace altfem
