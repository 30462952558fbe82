"""altfem.Scene validates exactly as the command line does."""
import json

import pytest

import altfem
from conftest import run_cli


def test_load_set_and_resolved(source):
    scene = altfem.Scene.load(source / "scenes/cantilever.json")
    scene.set("discretization/fem/element", "tet10").set("material/poisson_ratio", 0.25)
    resolved = scene.resolved("fem")
    assert resolved["discretization"]["fem"]["element"] == "tet10"
    assert resolved["material"]["poisson_ratio"] == 0.25
    assert resolved["solver"]["tolerance"] == 1e-5  # a default filled in


def test_a_dict_scene_equals_its_file(source):
    path = source / "scenes/cantilever.json"
    with open(path) as file:
        document = json.load(file)
    assert altfem.Scene(document).resolved("fem") == altfem.Scene.load(path).resolved("fem")


def test_bad_input_raises_with_the_command_lines_message(source, tmp_path):
    with open(source / "scenes/cantilever.json") as file:
        document = json.load(file)
    document["material"]["poisson_ratio"] = 0.5
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(document))
    code, _, error = run_cli("run", bad, "--method", "fem", "--out", tmp_path / "out")
    assert code == 2
    with pytest.raises(altfem.SceneError) as raised:
        altfem.Scene.load(bad)
    assert f"altfem: error: {raised.value}\n" == error
    assert not (tmp_path / "out").exists()


def test_a_bad_set_leaves_the_scene_unchanged(source):
    scene = altfem.Scene.load(source / "scenes/cantilever.json")
    with pytest.raises(altfem.SceneError, match="/material/poisson_ratio"):
        scene.set("material/poisson_ratio", 0.7)
    assert scene.resolved()["material"]["poisson_ratio"] == 0.3
    assert repr(scene).endswith("cantilever.json>")


def test_an_unknown_method_names_the_available_ones(source):
    scene = altfem.Scene.load(source / "scenes/cantilever.json")
    with pytest.raises(altfem.SceneError, match="available: fem, fcm, dg, harmonic"):
        altfem.run(scene, method="xfem")
    assert altfem.methods() == ["fem", "fcm", "dg", "harmonic"]
