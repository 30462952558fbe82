#!/usr/bin/python3
"""Adaptive against uniform refinement where the error concentrates, for the methods whose
error the energy cannot rank (issue #34): the L-shaped beam of re_entrant_study.py
(bench/scenes/l_beam.json, its re-entrant edge a stress singularity) solved by dg (k = 2)
and harmonic (trilinear hexahedra, a refined cell's neighbours MFS polyhedra) on the
sliced grid's whole cubes, uniform and by `refine` cycles
of the error indicator with bulk marking from the coarsest grid (1->8, each adaptive row a
run of its own), every run measured by `altfem compare` against one fine fcm run: Hex20 on
the 4 x 4 x 1 grid refined adaptively 10 times (240k DOFs: against it the 8-times refined
run's error is 7e-4 of the RMS displacement, the 9-times one's 3e-4, halving per cycle, so
its own is about 1.5e-4, far below every run's here). dg is not conforming, so its energy says nothing of its
error; the measure is the RMS surface error over the reference's RMS displacement.
Prints a convergence table per method and series, the cheapest adaptive run that reaches the
finest uniform run's error, and plots both series per method (re_entrant_methods_study.png).

    /usr/bin/python3 bench/re_entrant_methods_study.py [--altfem build/bin/altfem]
        [--out out/re_entrant_methods_study] [--fraction 0.5]
"""
import argparse
import json
import pathlib

from refine_study import compare, plot, report_reaching, table

ROOT = pathlib.Path(__file__).resolve().parent.parent
# Grid cells along the beam's 1 m sides, the grid on its bounds (no margin), so that every
# cell is whole: 4 is the 4 x 4 x 1 grid of 0.25 m cubes.
UNIFORM = {"dg": [4, 8, 16], "harmonic": [4, 8, 16, 32, 64]}
CYCLES = {"dg": list(range(1, 7)), "harmonic": list(range(1, 10))}


def refine_event(fraction, cycles):
    return [{"time": 0, "refine": {"criterion": "error_indicator", "fraction": fraction, "max_level": 10,
                                   "cycles": cycles}}]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--altfem", default=str(ROOT / "build/bin/altfem"))
    parser.add_argument("--out", default=str(ROOT / "out/re_entrant_methods_study"))
    parser.add_argument("--fraction", type=float, default=0.5)
    arguments = parser.parse_args()
    base = json.loads((ROOT / "bench/scenes/l_beam.json").read_text())
    for method in UNIFORM:
        base["discretization"][method] = {"mesh": "slice", "slice": {"resolution": 4, "margin_cells": 0}}
    reference = {"method": "fcm", "set": {"discretization/fcm/cell": "hex20",
                                          "events": refine_event(arguments.fraction, 10)}}
    out = pathlib.Path(arguments.out)
    series = {}
    for method in UNIFORM:
        uniform = dict(base, compare={"methods": [method], "reference": reference,
                                      "sweeps": {f"discretization/{method}/slice/resolution": UNIFORM[method]}})
        adaptive = dict(base, events=refine_event(arguments.fraction, 1),
                        compare={"methods": [method], "reference": reference,
                                 "sweeps": {"events/0/refine/cycles": CYCLES[method]}})
        by_dofs = lambda rows: sorted(rows, key=lambda r: int(r["dofs"]))
        series[(method, "uniform")] = by_dofs(compare(uniform, out / method / "uniform", arguments.altfem))
        series[(method, "adaptive")] = by_dofs(compare(adaptive, out / method / "adaptive", arguments.altfem))
    print(f"\nl_beam: uniform grids against error_indicator cycles (fraction {arguments.fraction:g}, 1->8); "
          "error: RMS surface error / RMS displacement against fcm Hex20, 10 adaptive cycles")
    for method in UNIFORM:
        table(f"{method}, uniform", series[(method, "uniform")])
        table(f"{method}, adaptive", series[(method, "adaptive")])
        report_reaching(method, series[(method, "uniform")], series[(method, "adaptive")])
    plot(series, out / "re_entrant_methods_study.png",
         "L-shaped beam (re-entrant edge): adaptive against uniform refinement, dg and harmonic")


if __name__ == "__main__":
    main()
