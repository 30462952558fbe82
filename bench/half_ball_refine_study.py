#!/usr/bin/python3
"""Adaptive against uniform refinement on the main job's manufactured half-ball (issue
#34): scenes/manufactured_half_ball.json, whose exact solution is smooth (sines and
cosines of the coordinates), solved by fcm (Hex20 on its background grid), dg (k = 2) and
harmonic (on the sliced grid's cells, cut cells MFS polyhedra) on uniform grids and by
`refine` cycles of the error indicator with bulk marking (fraction 0.5, 1->8) from the
coarsest grid, each adaptive row a run of its own. fem meshes the ball with tetrahedra,
which altfem does not refine (docs/architecture.md, "Events"). The error is the relative
H1 seminorm |u - u_h|_1 / |u|_1 against the exact field (summary.json's field_errors).
Prints a convergence table per method and series, the cheapest adaptive run that reaches
the finest uniform run's error, and plots both series per method (half_ball_refine_study.png).

    /usr/bin/python3 bench/half_ball_refine_study.py [--altfem build/bin/altfem]
        [--out out/half_ball_refine_study] [--fraction 0.5]
"""
import argparse
import json
import pathlib

from refine_study import compare, plot, report_reaching, table

ROOT = pathlib.Path(__file__).resolve().parent.parent
ERROR = "field_h1_error"
# Uniform grids (fcm: its background grid; dg, harmonic: the slicing's cells per side of
# the ball's bounds) and adaptive cycles from the first of them.
UNIFORM = {"fcm": ("discretization/fcm/resolution", [[4, 4, 2], [8, 8, 4], [16, 16, 8]]),
           "dg": ("discretization/dg/slice/resolution", [4, 8, 16]),
           "harmonic": ("discretization/harmonic/slice/resolution", [4, 8, 16, 32])}
CYCLES = {"fcm": [1, 2, 3, 4], "dg": [1, 2, 3, 4], "harmonic": [1, 2, 3, 4, 5]}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--altfem", default=str(ROOT / "build/bin/altfem"))
    parser.add_argument("--out", default=str(ROOT / "out/half_ball_refine_study"))
    parser.add_argument("--fraction", type=float, default=0.5)
    arguments = parser.parse_args()
    base = json.loads((ROOT / "scenes/manufactured_half_ball.json").read_text())
    base.pop("compare")
    base["output"] = {"volume": False, "surface": False}
    base["discretization"]["fcm"].update({"cell": "hex20", "resolution": UNIFORM["fcm"][1][0]})
    base["discretization"]["dg"] = {"degree": 2, "mesh": "slice", "slice": {"resolution": UNIFORM["dg"][1][0]}}
    base["discretization"]["harmonic"] = {"mesh": "slice", "slice": {"resolution": UNIFORM["harmonic"][1][0]}}
    refine = {"time": 0, "refine": {"criterion": "error_indicator", "fraction": arguments.fraction,
                                    "max_level": 10, "cycles": 1}}
    # `compare` needs a reference run for its surface errors, which this study does not read:
    # the cheapest run will do (without one, it would take each sweep's last run).
    reference = {"method": "fcm", "set": {"discretization/fcm/resolution": UNIFORM["fcm"][1][0], "events": []}}
    out = pathlib.Path(arguments.out)
    series = {}
    for method, (key, grids) in UNIFORM.items():
        uniform = dict(base, compare={"methods": [method], "reference": reference, "sweeps": {key: grids}})
        adaptive = dict(base, events=[refine], compare={"methods": [method], "reference": reference,
                                                        "sweeps": {"events/0/refine/cycles": CYCLES[method]}})
        by_dofs = lambda rows: sorted(rows, key=lambda r: int(r["dofs"]))
        series[(method, "uniform")] = by_dofs(compare(uniform, out / method / "uniform", arguments.altfem))
        series[(method, "adaptive")] = by_dofs(compare(adaptive, out / method / "adaptive", arguments.altfem))
    print(f"\nmanufactured half-ball: uniform grids against error_indicator cycles (fraction {arguments.fraction:g}, "
          "1->8); error: |u - u_h|_1 / |u|_1 against the exact field")
    for method in UNIFORM:
        table(f"{method}, uniform", series[(method, "uniform")], ERROR)
        table(f"{method}, adaptive", series[(method, "adaptive")], ERROR)
        report_reaching(method, series[(method, "uniform")], series[(method, "adaptive")], ERROR)
    plot(series, out / "half_ball_refine_study.png",
         "manufactured half-ball (smooth): adaptive against uniform refinement", ERROR, "|u - u_h|_1 / |u|_1")


if __name__ == "__main__":
    main()
