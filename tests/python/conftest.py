"""Shared fixtures of the Python module's tests: the source tree and the `altfem` executable
of the same build (ctest sets ALTFEM_SOURCE_DIR and PYTHONPATH; tests/python/CMakeLists.txt)."""
import json
import os
import pathlib
import subprocess

import pytest

import altfem

SOURCE = pathlib.Path(os.environ.get("ALTFEM_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture
def source():
    return SOURCE


def run_cli(*arguments):
    """`altfem ARGUMENTS...` of this build: (exit code, stdout, stderr)."""
    completed = subprocess.run([altfem._core.executable()] + [str(argument) for argument in arguments],
                               capture_output=True, text=True)
    return completed.returncode, completed.stdout, completed.stderr


def cli_summary(scene_file, method, out, *sets):
    """summary.json of `altfem run SCENE --method METHOD --out OUT --set ...`."""
    arguments = ["run", scene_file, "--method", method, "--out", out]
    for assignment in sets:
        arguments += ["--set", assignment]
    code, _, error = run_cli(*arguments)
    assert code == 0, error
    with open(os.path.join(out, "summary.json")) as file:
        return json.load(file)
