#pragma once
// Mesh_3 puts the surface vertices of a shape's flat face on its level set only to its
// error bound (a half-ball's flat face at z = ±1e-7), which leaves the face bent by that
// much: a cell sliced from such a surface is not convex to round-off, so a refinement
// skips it, and a region through the plane holds some of its faces and not others.
// Snapping those vertices onto the plane makes the face flat again.
#include <vector>

#include "shared/geometry/analytic_shape.hpp"
#include "shared/mesh/volume_mesh.hpp"

namespace altfem {

/// Moves each boundary node of `mesh` (a Tet4 mesh of a shape) that lies within
/// `tolerance` of one of `faces` (inside its rectangle, enlarged by `tolerance`) onto that
/// face's plane: exactly onto it for an axis-aligned plane (the coordinate set), else by
/// its projection. A move that would turn a tetrahedron's orientation is not made (the
/// node stays). Returns the number of nodes moved.
int snap_to_planar_faces(VolumeMesh& mesh, const std::vector<PlanarFace>& faces, double tolerance);

}  // namespace altfem
