"""altfem.compare: `altfem compare`, its results table returned as a list of dicts."""
import csv
import json
import os

from ._command import run_command
from ._scene import as_scene


def _number(text):
    """A results.csv cell as int or float where it is one, else the text ('' stays '')."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def compare(scene, out, methods=None, sweeps=None, reference=None, jobs=1, force=False):
    """Runs every configuration of `scene` (a Scene, or a scene file's path) as `altfem compare` does and returns
    results.csv as a list of dicts, one per run (docs/architecture.md, "altfem compare":
    DOFs, time, the surface error against the reference, ...), numbers as numbers.

    out:       the folder for results.csv, report.md, plots and runs/ (required: runs are
               kept there, and a second call resumes them unless `force`)
    methods:   a list of methods (default: the scene's compare block, else every method)
    sweeps:    {"discretization/fem/resolution": [[10, 1, 1], [20, 2, 2]], ...}: the values
               of each key (replace the scene's sweeps)
    reference: "METHOD[:KEY=VALUE,...]" (default: the scene's, else the finest run)
    jobs:      runs at a time (the cores are divided among them)
    """
    os.makedirs(out, exist_ok=True)
    arguments = ["compare", as_scene(scene)._file_for_commands(out), "--out", out, "--jobs", jobs]
    if methods:
        arguments += ["--methods", ",".join(methods)]
    for key, values in (sweeps or {}).items():
        arguments += ["--sweep", f"{key}={','.join(json.dumps(value, separators=(',', ':')) for value in values)}"]
    if reference:
        arguments += ["--reference", reference]
    if force:
        arguments.append("--force")
    run_command(arguments)
    with open(os.path.join(out, "results.csv"), newline="") as table:
        return [{key: _number(value) for key, value in row.items()} for row in csv.DictReader(table)]
