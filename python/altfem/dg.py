"""altfem.dg: the element matrices of interior-penalty DG on one polyhedron
(Kaufmann et al. 2009, §5 and Appendix A), integrated exactly as the `dg` method does."""
import numpy as np

from . import _core


def element_matrices(vertices, faces, degree=2, youngs_modulus=1.0, poisson_ratio=0.3, density=1.0):
    """The volume matrices of one DG element with `vertices` ((n, 3), m) and `faces` (lists
    of vertex ids, counter-clockwise seen from outside; convex or not), for isotropic
    linear elasticity with the monomials ((x − c)/h)^α, |α| ≤ degree (c the centroid, h
    the diameter): 4, 10 or 20 functions for degree 1, 2, 3.

    Every integral is exact: products of monomials are monomials, whose integrals over a
    polyhedron the divergence theorem turns into face integrals. Returns a dict:
      stiffness  (3m, 3m), DOF 3a+i: ∫ 2μ ε(φ_b e_k):ε(φ_a e_i) + λ div(φ_b e_k) div(φ_a e_i) dV, N/m
      mass       (m, m): ρ ∫ φ_a φ_b dV, kg (the same for each component)
      integrals  (m,): ∫ φ_a dV, m³
      exponents  (m, 3): α of each function; centre (3,) c and scale h, m
    Raises ValueError for a degree outside 1..3 or faces naming missing vertices.
    """
    return _core.dg_element_matrices(np.asarray(vertices, dtype=float), [list(map(int, face)) for face in faces],
                                     degree, youngs_modulus, poisson_ratio, density)
