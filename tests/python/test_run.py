"""altfem.run: the command line's run, in this process, its frames as numpy views."""
import gc

import numpy
import pytest

import altfem
from conftest import cli_summary

def comparable(summary):
    """The summary without what differs between two identical runs: the environment and
    every time (keys ending in _s, the project's name for seconds)."""
    if isinstance(summary, dict):
        return {key: comparable(value) for key, value in summary.items()
                if key != "environment" and not key.endswith("_s")}
    if isinstance(summary, list):
        return [comparable(value) for value in summary]
    return summary


@pytest.mark.parametrize("method", ["fem", "fcm", "dg", "harmonic"])
def test_the_summary_equals_the_command_lines_bit_for_bit(source, tmp_path, method):
    scene_file = source / "tests/cli/scenes/tiny_beam.json"
    expected = cli_summary(scene_file, method, tmp_path / "cli", "time/static=true", "time/load_steps=3")
    scene = altfem.Scene.load(scene_file).set("time/static", True).set("time/load_steps", 3)
    result = altfem.run(scene, method=method, out=tmp_path / "python")
    assert comparable(result.summary) == comparable(expected)
    assert result.summary["surface"] == expected["surface"]
    assert (tmp_path / "python" / "summary.json").exists()


def test_frames_have_the_documented_shapes_and_outlive_the_result(source):
    scene = altfem.Scene.load(source / "tests/cli/scenes/tiny_beam.json")
    result = altfem.run(scene.set("time/static", True).set("time/load_steps", 3), method="fem")
    assert result.out is None
    assert [frame.time for frame in result.frames] == pytest.approx([0, 1 / 3, 2 / 3, 1])  # load factors
    last = result.frames[-1]
    cells = result.summary["elements"]["hex8"]
    assert last.points.shape == last.displacement.shape == (len(last.points), 3)
    assert last.cell_types.shape == (cells,) and set(last.cell_types) == {12}  # VTK_HEXAHEDRON
    assert last.offsets[-1] == len(last.connectivity) == 8 * cells
    assert last.stress.shape == (cells, 3, 3)
    deviator = last.stress - numpy.trace(last.stress, axis1=1, axis2=2)[:, None, None] / 3 * numpy.eye(3)
    numpy.testing.assert_allclose(last.von_mises, numpy.sqrt(1.5 * (deviator**2).sum(axis=(1, 2))), rtol=1e-12)
    assert last.surface_vertices.shape == last.surface_displacement.shape
    assert last.surface_triangles.shape[1] == 3 and last.surface_triangles.max() < len(last.surface_vertices)
    assert not last.displacement.flags.owndata  # a view of the run's memory, not a copy
    copy = last.surface_displacement.copy()
    view = last.surface_displacement
    del result, last
    gc.collect()
    numpy.testing.assert_array_equal(view, copy)  # the view keeps the run's memory alive
    assert view[:, 2].min() < 0  # the beam sags under gravity


def test_a_numerical_failure_raises_and_keeps_the_partial_result(source, tmp_path):
    scene = altfem.Scene.load(source / "tests/cli/scenes/newton_fails.json")
    with pytest.raises(altfem.NumericalError, match="step 1") as raised:
        altfem.run(scene, method="fem", out=tmp_path / "run")
    partial = raised.value.result
    assert partial.summary["status"].startswith("error: ")
    assert partial.summary["newton_iterations"] > 0
    assert len(partial.frames) == 1 and partial.frames[0].time == 0  # the initial state only
    assert numpy.all(partial.frames[0].displacement == 0)
