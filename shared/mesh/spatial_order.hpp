#pragma once
// Renumbering a mesh so that neighbours in space are neighbours in memory.
//
// Why: Mesh_3 lists cells and vertices in the order its refinement created them,
// which is close to random in space. Assembly then scatters each element into
// matrix rows far from the previous element's, and the two threads of a colour write
// all over the matrix: on the 30,675-DOF twisting beam a second thread did not speed
// assembly up at all (0.083-0.093 s per Newton iteration with 1 thread, 0.091-0.096 s
// with 2). Sorting cells along a Hilbert curve and numbering nodes in the order the
// sorted cells first use them restores the locality a structured grid has.
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// `mesh` with its cells sorted along a Hilbert curve through their centroids
/// (CGAL::hilbert_sort, deterministic) and its nodes renumbered by first use in
/// the sorted cells; nodes no cell uses keep their relative order at the end.
/// Geometry, element type and each cell's node order are unchanged.
VolumeMesh spatially_ordered(const VolumeMesh& mesh);

}  // namespace altfem
