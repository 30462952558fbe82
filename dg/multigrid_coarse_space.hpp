#pragma once
// The coarse level of PETSc's multigrid for DG (solver.p_multigrid,
// shared/solve/petsc_coarse_level.hpp): the vertex space (vertex_coarse_space.hpp) where
// it has fewer unknowns than the DG space, else degree ≥ 2's affine functions
// (affine_coarse_space.hpp). On the vertex space GAMG sees a first-order operator — on
// simplices exactly the continuous P1 stiffness, whose fits are conforming there (Dobrev,
// Lazarov, Vassilevski & Zikatanov 2006, §3) — where on the whole k = 1 space it
// aggregates monomial blocks: CG took 35-39 iterations on the k = 1 cantilever and 31 a
// solve on the tetrahedralized ball, against 18-29 and 20, and 71-87 on k = 2 against 21-34
// (docs/performance.md).
#include "dg/dg_linear_system.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"
#include "shared/solve/coarse_space.hpp"

namespace altfem::dg {

/// The coarse space of `mesh`, whose cells are `system`'s (same order): one scalar
/// function per vertex, its near-null space the rigid motions at the vertices; or the
/// affine functions of degree ≥ 2 (fine_function their own); empty for degree 1 without
/// a coarser vertex space, and where strong conditions recombine cells' functions (which
/// neither space then fits).
CoarseSpace multigrid_coarse_space(const PolyhedralMesh& mesh, const DgLinearSystem& system);

}  // namespace altfem::dg
