"""altfem.mesh: a method's mesh as arrays, as `altfem mesh` builds it."""
import numpy as np
import pytest

import altfem


def test_fem_mesh_of_the_cantilever(source):
    mesh = altfem.mesh(altfem.Scene.load(source / "scenes/cantilever.json"), "fem")
    assert mesh.points.shape[1] == 3
    assert list(mesh.cell_types) == [25] * (20 * 2 * 2)  # VTK_QUADRATIC_HEXAHEDRON
    assert mesh.offsets[-1] == len(mesh.connectivity) == 20 * 80 and len(mesh.cell(79)) == 20
    assert mesh.polyhedron_faces is None
    np.testing.assert_allclose(mesh.points.min(axis=0), [0, 0, 0], atol=1e-15)
    np.testing.assert_allclose(mesh.points.max(axis=0), [1, 0.1, 0.1], rtol=1e-15)


def test_sliced_dg_cells_fill_the_box_and_list_their_faces(source):
    mesh = altfem.mesh(altfem.Scene.load(source / "scenes/cantilever.json"), "dg", source="slice", resolution=10)
    cells = len(mesh.cell_types)
    assert set(mesh.cell_types) == {42} and len(mesh.polyhedron_faces) == cells
    # The box is sliced into its own grid: the cells' volumes add up to 1 × 0.1 × 0.1.
    assert mesh.cell_data["volume"].sum() == pytest.approx(0.01, rel=1e-12)
    first = mesh.polyhedron_faces[0]
    assert set(np.concatenate(first)) == set(mesh.cell(0))
    assert mesh.facts["cells"]["total"] == cells


def test_bad_options_raise():
    with pytest.raises(ValueError, match="resolution: must be >= 1"):
        altfem.mesh(None, "dg", resolution=0)
