"""altfem.harmonic: the harmonic basis of one polyhedral element (Martin et al. 2008, §4–5),
the one the `harmonic` method builds on every cell that is not a plain tetrahedron or box."""
import numpy as np

from . import _core


def basis(vertices, faces, edge_samples=4, offset=0.2):
    """The harmonic node functions N_i of the polyhedron with `vertices` ((n, 3), m) and
    `faces` (lists of vertex ids, counter-clockwise seen from outside; convex or not).

    Each N_i is harmonic inside (ΔN_i = 0) and on the boundary equals the faces' 2D
    harmonic coordinates (1 at vertex i, 0 at the others, linear along edges),
    approximated by the method of fundamental solutions (eq. 11):
    N_i(x) = Σ_j w_ij / ‖x − k_j‖ + a_i·x + a_i0 with kernel centres k_j outside,
    `edge_samples` centres per edge and moved out by `offset` × the element's diameter.

    The returned object has: node_count; values(points) → (m, n) array of N_i(x_q);
    gradients(points) → (m·n, 3), row q·n + i holding ∇N_i(x_q); centres → (#centres, 3);
    boundary_residual (the fit's RMS misfit of the boundary data).
    Raises ValueError for arrays of the wrong shape or faces naming missing vertices.
    """
    return _core.HarmonicBasis(np.asarray(vertices, dtype=float), [list(map(int, face)) for face in faces],
                               edge_samples, offset)


def winding_number(vertices, faces, points):
    """The winding number of the polyhedron about each point ((m, 3) → (m,)): 1 inside,
    0 outside, ½ on a face."""
    return _core.winding_number(np.asarray(vertices, dtype=float), [list(map(int, face)) for face in faces],
                                np.atleast_2d(np.asarray(points, dtype=float)))
