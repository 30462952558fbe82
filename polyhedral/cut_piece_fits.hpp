#pragma once
// The check a cut's new cells pass before they become harmonic elements (issue #33; Martin
// et al. 2008 §8 give each cut element a new harmonic basis): a cell whose MFS fit fails,
// or misses its boundary data — the faces' harmonic coordinates, a partition of unity —
// by more than a tolerance, is refused, and the cut merges it into a neighbour
// (cut_polyhedral_scene_mesh's RefusedPieces) as it merges a negligible piece, where its
// basis would have made the stiffness wrong or the run stop.
#include <vector>

#include "polyhedral/harmonic_basis_memory.hpp"
#include "polyhedral/harmonic_scene_block.hpp"
#include "shared/mesh/polyhedral_mesh.hpp"

namespace altfem::harmonic {

/// Per cell of `candidates` (cells of `pieces`, geometry computed), whether its fit fails:
/// not finite, or an RMS boundary misfit above `max_residual`. Only shapes new to the run
/// are fitted — a plain Tet4/Hex8 cell (with `kind` automatic) or a shape `memory` holds
/// was built before — each once, in parallel over shapes (OpenMP); the fits that pass go
/// into `memory`, where the build on the cut mesh finds them instead of fitting again.
std::vector<bool> cells_whose_fit_fails(const PolyhedralMesh& pieces, const std::vector<int>& candidates,
                                        HarmonicBasisKind kind, const MfsOptions& options, double max_residual,
                                        HarmonicBasisMemory& memory);

}  // namespace altfem::harmonic
