"""altfem.compare and altfem.quadrature: the command line's tables, as Python data."""
import csv
import math

import numpy
import pytest

import altfem


def test_compare_returns_results_csv_as_numbers(source, tmp_path):
    scene = altfem.Scene.load(source / "tests/cli/scenes/tiny_beam.json").set("material/youngs_modulus", 2e6)
    rows = altfem.compare(scene, out=tmp_path, methods=["fem", "fcm"],
                          sweeps={"discretization/fem/resolution": [[2, 1, 1], [4, 2, 2]]})
    with open(tmp_path / "results.csv", newline="") as table:
        written = list(csv.DictReader(table))
    assert len(rows) == len(written) >= 3  # fem × 2 resolutions, fcm, and the reference
    for row, text in zip(rows, written):
        assert row.keys() == text.keys()
        assert row["dofs"] == int(text["dofs"]) > 0
    assert (tmp_path / "report.md").exists()
    assert (tmp_path / "scene.json").exists()  # the scene with its set value, for the executable
    assert all(row["status"] == "ok" for row in rows)


def test_compare_of_a_bad_method_raises_scene_error(source, tmp_path):
    scene = altfem.Scene.load(source / "tests/cli/scenes/tiny_beam.json")
    with pytest.raises(altfem.SceneError, match="--methods"):
        altfem.compare(scene, out=tmp_path, methods=["xfem"])


def test_monomials_meet_figure_4s_bounds():
    rows = altfem.quadrature.monomials("hex20", order=3)
    assert [row["order"] for row in rows] == [1, 2, 3]
    for row in rows:
        assert row["basis_size"] == math.comb(row["order"] + 3, 3)
        assert row["simplified"]["points"] <= row["basis_size"]
        assert row["simplified"]["max_relative_error"] <= 1e-11


def test_a_cut_cells_rules_integrate_its_clipped_volume(source):
    scene = altfem.Scene.load(source / "scenes/sphere.json")
    rules = altfem.quadrature.cut_cell(scene, cell=(0, 1, 1), resolution=3, order=3)
    assert rules["cut_cells"] == 1
    simplified, initial = rules["simplified"], rules["initial"]
    assert simplified["points"].shape == (len(simplified["weights"]), 3)
    assert len(simplified["weights"]) <= math.comb(3 + 3, 3) < len(initial["weights"])
    for rule in (initial, simplified):
        assert rule["physical_weights"].sum() == pytest.approx(rules["clipped_volume"], rel=1e-12)
        assert numpy.all(rule["physical_weights"] > 0)
