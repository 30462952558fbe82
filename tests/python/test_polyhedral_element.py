"""altfem.harmonic and altfem.dg: one polyhedral element's basis and matrices, from Python arrays."""
import numpy as np
import pytest

import altfem

CUBE = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=float)
CUBE_FACES = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]


def test_a_cubes_basis_is_a_partition_of_unity_reproducing_linear_fields():
    basis = altfem.harmonic.basis(CUBE, CUBE_FACES)
    points = np.random.default_rng(1).uniform(0.05, 0.95, (50, 3))
    values = basis.values(points)
    assert basis.node_count == 8 and values.shape == (50, 8)
    np.testing.assert_allclose(values.sum(axis=1), 1, atol=1e-10)
    np.testing.assert_allclose(values @ CUBE, points, atol=1e-10)
    gradients = basis.gradients(points).reshape(50, 8, 3)
    np.testing.assert_allclose(gradients.sum(axis=1), 0, atol=1e-9)  # ∇ Σ N_i = ∇1 = 0
    # The harmonic function with trilinear boundary data on a box is the trilinear one,
    # which the fit approaches (docs/performance.md: 6.6e-4 at 4 samples per edge).
    x, y, z = points.T
    trilinear_first = (1 - x) * (1 - y) * (1 - z)
    assert np.abs(values[:, 0] - trilinear_first).max() < 2e-3


def test_winding_numbers_and_bad_polyhedra():
    numbers = altfem.harmonic.winding_number(CUBE, CUBE_FACES, [[0.5, 0.5, 0.5], [1.5, 0.5, 0.5]])
    np.testing.assert_allclose(numbers, [1, 0], atol=1e-12)
    with pytest.raises(ValueError, match=r"faces\[1\]: vertex 9 is not one of the 8 vertices"):
        altfem.harmonic.basis(CUBE, [CUBE_FACES[0], [4, 5, 9, 6]] + CUBE_FACES[2:])
    with pytest.raises(ValueError, match="points: expected an"):
        altfem.harmonic.basis(CUBE, CUBE_FACES).values(np.zeros((3, 2)))


def test_dg_element_matrices_of_a_cube_hold_the_energy_of_a_uniform_stretch():
    matrices = altfem.dg.element_matrices(CUBE, CUBE_FACES, degree=2, youngs_modulus=26.0, poisson_ratio=0.3,
                                          density=2.0)
    stiffness, exponents = matrices["stiffness"], matrices["exponents"]
    assert stiffness.shape == (30, 30) and exponents.shape == (10, 3)
    np.testing.assert_allclose(stiffness, stiffness.T, atol=1e-12)
    assert matrices["integrals"][0] == pytest.approx(1.0, rel=1e-14)  # φ_0 = 1: the volume
    assert matrices["mass"][0, 0] == pytest.approx(2.0, rel=1e-14)
    # u = (x, 0, 0) = (c_x + h X, 0, 0): coefficients of the constant and of X in component 0.
    stretch = np.zeros(30)
    stretch[3 * 0 + 0] = matrices["centre"][0]
    stretch[3 * int(np.flatnonzero((exponents == [1, 0, 0]).all(axis=1))[0]) + 0] = matrices["scale"]
    lam, mu = 15.0, 10.0  # E = 26, ν = 0.3
    assert stretch @ stiffness @ stretch == pytest.approx(lam + 2 * mu, rel=1e-12)  # ∫ σ:ε over the unit cube
    eigenvalues = np.linalg.eigvalsh(stiffness)
    assert np.sum(eigenvalues < 1e-10 * eigenvalues.max()) == 6  # the rigid motions, nothing else
    with pytest.raises(ValueError, match="degree: expected 1, 2 or 3"):
        altfem.dg.element_matrices(CUBE, CUBE_FACES, degree=4)
