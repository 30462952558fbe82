#!/usr/bin/python3
"""Adaptive against uniform refinement on the manufactured half-ball (issue #34):
scenes/manufactured_half_ball_peak.json (`--scene peak`, the default: a peak of width
0.11 inside the ball, where adaptivity should pay) or scenes/manufactured_half_ball.json
(`--scene smooth`: the main job's sines and cosines, error spread over the whole ball).
Solved by fcm (Hex20 on its background grid), dg (k = 2) and harmonic (both on the sliced
grid's cells, cut cells MFS polyhedra for harmonic) on uniform grids and by `refine` cycles
of the error indicator with bulk marking (1->8) from the coarsest grid, each adaptive row a
run of its own. fem meshes the ball with tetrahedra, which altfem does not refine
(docs/architecture.md, "Events"). The error is the relative H1 seminorm |u - u_h|_1 / |u|_1
against the exact field (summary.json's field_errors). Prints a convergence table per
method and series, the cheapest adaptive run that reaches the finest uniform run's error
(issue #34: with <= 1/3 of its DOFs and <= 1/2 of its time), and plots both series per
method (half_ball_refine_study.png).

    /usr/bin/python3 bench/half_ball_refine_study.py [--scene peak|smooth]
        [--altfem build/bin/altfem] [--out out/half_ball_refine_study] [--fraction 0.5]
        [--methods fcm dg harmonic]

The peak's finest uniform grids peak at 4 GB (fcm 32 x 32 x 16, 133k DOFs) and 12.4 GB
(harmonic 64 cells per side, 295k DOFs, 80 s); dg's stop at 16 cells per side (45k DOFs),
the next (360k) being beyond 24 GB for CHOLMOD.
"""
import argparse
import json
import pathlib

from refine_study import compare, plot, report_reaching, table

ROOT = pathlib.Path(__file__).resolve().parent.parent
ERROR = "field_h1_error"
KEYS = {"fcm": "discretization/fcm/resolution", "dg": "discretization/dg/slice/resolution",
        "harmonic": "discretization/harmonic/slice/resolution"}
# Per scene: each method's uniform grids (fcm: its background grid; dg, harmonic: the
# slicing's cells per side of the ball's bounds) and adaptive cycles from the first of them.
STUDIES = {
    "smooth": {"file": "manufactured_half_ball.json",
               "uniform": {"fcm": [[4, 4, 2], [8, 8, 4], [16, 16, 8]], "dg": [4, 8, 16], "harmonic": [4, 8, 16, 32]},
               "cycles": {"fcm": [1, 2, 3, 4], "dg": [1, 2, 3, 4], "harmonic": [1, 2, 3, 4, 5]}},
    "peak": {"file": "manufactured_half_ball_peak.json",
             "uniform": {"fcm": [[4, 4, 2], [8, 8, 4], [16, 16, 8], [32, 32, 16]], "dg": [4, 8, 16],
                         "harmonic": [4, 8, 16, 32, 64]},
             "cycles": {"fcm": [2, 3, 4, 5, 6], "dg": [3, 4, 5, 6, 7], "harmonic": [3, 4, 5, 6, 7, 8]}},
}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scene", choices=list(STUDIES), default="peak")
    parser.add_argument("--altfem", default=str(ROOT / "build/bin/altfem"))
    parser.add_argument("--out", default=str(ROOT / "out/half_ball_refine_study"))
    parser.add_argument("--fraction", type=float, default=0.5)
    parser.add_argument("--methods", nargs="+", choices=list(KEYS), default=list(KEYS))
    arguments = parser.parse_args()
    study = STUDIES[arguments.scene]
    uniform_grids, cycles = study["uniform"], study["cycles"]
    base = json.loads((ROOT / "scenes" / study["file"]).read_text())
    base.pop("compare")
    base.pop("events", None)
    base["output"] = {"volume": False, "surface": False}
    base["discretization"]["fcm"].update({"cell": "hex20", "resolution": uniform_grids["fcm"][0]})
    base["discretization"]["dg"] = {"degree": 2, "mesh": "slice", "slice": {"resolution": uniform_grids["dg"][0]}}
    base["discretization"]["harmonic"] = {"mesh": "slice", "slice": {"resolution": uniform_grids["harmonic"][0]}}
    refine = {"time": 0, "refine": {"criterion": "error_indicator", "fraction": arguments.fraction,
                                    "max_level": 10, "cycles": 1}}
    # `compare` needs a reference run for its surface errors, which this study does not read:
    # the cheapest run will do (without one, it would take each sweep's last run).
    reference = {"method": "fcm", "set": {KEYS["fcm"]: uniform_grids["fcm"][0], "events": []}}
    out = pathlib.Path(arguments.out) / arguments.scene
    series = {}
    for method in arguments.methods:
        uniform = dict(base, compare={"methods": [method], "reference": reference,
                                      "sweeps": {KEYS[method]: uniform_grids[method]}})
        adaptive = dict(base, events=[refine], compare={"methods": [method], "reference": reference,
                                                        "sweeps": {"events/0/refine/cycles": cycles[method]}})
        by_dofs = lambda rows: sorted(rows, key=lambda r: int(r["dofs"]))
        series[(method, "uniform")] = by_dofs(compare(uniform, out / method / "uniform", arguments.altfem))
        series[(method, "adaptive")] = by_dofs(compare(adaptive, out / method / "adaptive", arguments.altfem))
    print(f"\n{study['file']}: uniform grids against error_indicator cycles (fraction {arguments.fraction:g}, "
          "1->8); error: |u - u_h|_1 / |u|_1 against the exact field")
    for method in arguments.methods:
        table(f"{method}, uniform", series[(method, "uniform")], ERROR)
        table(f"{method}, adaptive", series[(method, "adaptive")], ERROR)
        report_reaching(method, series[(method, "uniform")], series[(method, "adaptive")], ERROR)
    plot(series, out / "half_ball_refine_study.png",
         f"{study['file']}: adaptive against uniform refinement", ERROR, "|u - u_h|_1 / |u|_1")


if __name__ == "__main__":
    main()
