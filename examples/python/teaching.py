"""What every script of the teaching track shares: finding the module of this checkout's
build, the command line (--quick, --out), checks that count, and saving figures."""
import argparse
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
# The module this checkout built (scripts/setup builds it into build/python), unless
# PYTHONPATH already names one.
sys.path.append(str(ROOT / "build" / "python"))

import altfem  # noqa: E402
import matplotlib  # noqa: E402

matplotlib.use("Agg")  # PNG files, no display needed
import matplotlib.pyplot as plt  # noqa: E402,F401  (the scripts draw with it)

_failures = []


def arguments(description):
    """--quick (the smallest sizes, what the tests run) and --out (where the PNG goes)."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--quick", action="store_true", help="the smallest sizes only (seconds)")
    parser.add_argument("--out", default="out/examples", help="folder for the figure (default out/examples)")
    return parser.parse_args()


def check(condition, what):
    """Prints one line, PASS or FAIL; finish() exits non-zero when any failed."""
    print(f"{'PASS' if condition else 'FAIL'}: {what}")
    if not condition:
        _failures.append(what)


def scene(name):
    """A scene shipped in scenes/ of this checkout."""
    return altfem.Scene.load(ROOT / "scenes" / f"{name}.json")


def tip(frame, axis=0):
    """The mean displacement (3,) of the embedded surface's vertices at the far end along
    `axis` (the largest coordinate): the tip of a beam."""
    vertices, displacement = frame.surface_vertices, frame.surface_displacement
    end = vertices[:, axis] >= vertices[:, axis].max() - 1e-9
    return displacement[end].mean(axis=0)


def save(figure, folder, name):
    path = pathlib.Path(folder) / f"{name}.png"
    path.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(path, dpi=120, bbox_inches="tight")
    print(f"figure: {path}")


def finish():
    if _failures:
        print(f"{len(_failures)} check(s) failed")
        sys.exit(1)
    print("all checks passed")
