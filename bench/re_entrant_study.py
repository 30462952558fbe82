#!/usr/bin/python3
"""Adaptive against uniform refinement where the error concentrates (issue #34): an L-shaped
beam (bench/scenes/l_beam.json: two boxes, 1 x 1 x 0.25 m overall, clamped at y = 1 and
bending under its weight along -y), whose re-entrant edge at x = y = 0.5 is a stress
singularity, solved by fcm and fem on uniform Hex8 and Hex20 grids and adaptively from the
coarsest grid by `refine` cycles of the error indicator with bulk marking (`fraction`: the
cells carrying that share of h |[sigma n]|^2; 1->8, hanging nodes constrained). fem's grid
is the beam's bounds without the empty quadrant's cells (`grid` on a shape built of boxes);
fcm keeps the same cells, so their uniform runs are the same space, and their adaptive runs
differ by the indicator (fem's weighs the boundary faces against the loads, fcm's leaves
them out: the body's boundary crosses its cut cells in general).

dg (k = 2 on the sliced grid's whole cubes, 4 to 32 cells per metre) joins them: its
interior-penalty form a_h is symmetric and consistent, so with Galerkin orthogonality
Pi_h(u_h) - Pi(u) = 1/2 a_h(u - u_h, u - u_h), its DG energy norm with the consistency
terms: its energy ranks its runs too. Its Pi(u) is fem Hex20's (its own three finest uniform
runs extrapolate to about 0.01 J above it).

The comparison needs no reference solution. For a conforming method integrated exactly
(fcm: every cell is whole or empty, its rules are exact for the stiffness and the constant
load; fem: Hex8 at its default strength 2, Hex20 at strength 6), the static total energy is
the potential energy Pi(u_h), and
Pi(u_h) - Pi(u) = 1/2 |u - u_h|^2 in the energy norm: a lower energy is a smaller error.
So an adaptive run "reaches the finest uniform run's error" when its energy is at most
that run's. For the tables and the plot, the energy-norm error is estimated against Pi(u)
extrapolated from the three finest uniform runs (Aitken), and printed with its rate.

    /usr/bin/python3 bench/re_entrant_study.py [--altfem build/bin/altfem] [--out out/re_entrant_study]
        [--fraction 0.5]
"""
import argparse
import json
import math
import pathlib
import subprocess
import time

from study_plot import line_style, plot_error_against_cost

ROOT = pathlib.Path(__file__).resolve().parent.parent
UNIFORM = {"hex8": [[4, 4, 1], [8, 8, 2], [16, 16, 4], [32, 32, 8], [64, 64, 16]],
           "hex20": [[4, 4, 1], [8, 8, 2], [16, 16, 4], [32, 32, 8]],
           "k2": [[4, 4, 1], [8, 8, 2], [16, 16, 4], [32, 32, 8]]}
# Refinement cycles of the adaptive runs, each a run of its own from the coarsest grid (so
# that its time is the whole road to its mesh).
CYCLES = {"hex8": range(3, 10), "hex20": range(2, 8), "k2": range(2, 7)}
SERIES = [("fcm", "hex8"), ("fcm", "hex20"), ("fem", "hex8"), ("fem", "hex20"), ("dg", "k2")]


def discretization(method, cell, resolution):
    """The method's block for `cell` on the grid of `resolution`."""
    if method == "dg":  # cells per metre on the bounds: every cell a whole cube
        return {"dg": {"degree": 2, "mesh": "slice", "slice": {"resolution": resolution[0], "margin_cells": 0}}}
    if method == "fcm":
        return {"fcm": {"cell": cell, "resolution": resolution, "stabilization": 0}}
    # Strength 6 integrates an affine Hex20's stiffness exactly (degree <= 4 per axis).
    return {"fem": {"element": cell, "mesh": "grid", "resolution": resolution,
                    "quadrature_order": 6 if cell == "hex20" else 2}}


def run(altfem, method, scene, out):
    """One `altfem run` of `scene` (a dict); returns (DOFs, final total energy, wall seconds)."""
    out.mkdir(parents=True, exist_ok=True)
    path = out / "scene.json"
    path.write_text(json.dumps(scene, indent=1))
    start = time.perf_counter()
    subprocess.run([altfem, "run", str(path), "--method", method, "--out", str(out / "run")], check=True,
                   stdout=subprocess.DEVNULL)
    seconds = time.perf_counter() - start
    last = [line.split() for line in (out / "run/log.txt").read_text().splitlines() if not line.startswith("#")][-1]
    return int(last[2]), float(last[6]), seconds


def extrapolated_energy(energies):
    """Pi(u) from the last three energies of a sequence refined by one factor (Aitken's delta squared)."""
    a, b, c = energies[-3:]
    return c - (c - b) ** 2 / ((c - b) - (b - a))


def table(title, rows, limit):
    print(f"\n{title}")
    print(f"{'run':28} {'DOFs':>8} {'energy [J]':>12} {'energy error':>13} {'time [s]':>9} {'rate':>6}")
    previous = None
    for label, dofs, energy, seconds in rows:
        error = math.sqrt(max(2 * (energy - limit), 0.0))
        # error ~ DOFs^(-rate/3): the rate in h of a 3D mesh.
        rate = "" if previous is None or error == 0 else \
            f"{-3 * math.log(error / previous[1]) / math.log(dofs / previous[0]):6.2f}"
        print(f"{label:28} {dofs:8d} {energy:12.6f} {error:13.4e} {seconds:9.2f} {rate:>6}")
        previous = (dofs, error)


def plot(series, limit, path):
    """Energy-norm error against DOFs and against seconds, uniform and adaptive per cell."""
    lines = {}
    colours = {("fcm", "hex8"): "C0", ("fcm", "hex20"): "C1", ("fem", "hex8"): "C2", ("fem", "hex20"): "C3",
               ("dg", "k2"): "C4"}
    for (method, cell, kind), rows in series.items():
        points = [(row[1], row[3], math.sqrt(max(2 * (row[2] - limit[(method, cell)]), 1e-30))) for row in rows]
        lines[f"{method} {cell} {kind}"] = (line_style(kind == "uniform", colours[(method, cell)]), points)
    plot_error_against_cost(lines, "energy-norm error [J^1/2]",
                            "L-shaped beam (re-entrant edge): adaptive against uniform refinement", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--altfem", default=str(ROOT / "build/bin/altfem"))
    parser.add_argument("--out", default=str(ROOT / "out/re_entrant_study"))
    parser.add_argument("--fraction", type=float, default=0.5)
    arguments = parser.parse_args()
    base = json.loads((ROOT / "bench/scenes/l_beam.json").read_text())
    out = pathlib.Path(arguments.out)
    series, limit = {}, {}
    for method, cell in SERIES:
        uniform = []
        for resolution in UNIFORM[cell]:
            scene = dict(base, discretization=discretization(method, cell, resolution))
            label = f"uniform {resolution[0]}x{resolution[1]}x{resolution[2]}"
            uniform.append((label, *run(arguments.altfem, method, scene,
                                        out / method / cell / label.replace(" ", "_"))))
        adaptive = []
        for cycles in CYCLES[cell]:
            scene = dict(base, discretization=discretization(method, cell, UNIFORM[cell][0]))
            scene["events"] = [{"time": 0, "refine": {"criterion": "error_indicator",
                                                      "fraction": arguments.fraction,
                                                      "max_level": 10, "cycles": cycles}}]
            label = f"adaptive, {cycles} cycles"
            adaptive.append((label, *run(arguments.altfem, method, scene,
                                         out / method / cell / f"adaptive_{cycles}")))
        adaptive.sort(key=lambda row: row[1])
        name = f"{method} {cell}"
        limit[(method, cell)] = limit[("fem", "hex20")] if method == "dg" else \
            extrapolated_energy([row[2] for row in uniform])
        series[(method, cell, "uniform")], series[(method, cell, "adaptive")] = uniform, adaptive
        source = "fem hex20's" if method == "dg" else "extrapolated from the uniform runs"
        print(f"\n{name}: Pi(u) {source}: {limit[(method, cell)]:.6f} J")
        table(f"{name}, uniform", uniform, limit[(method, cell)])
        table(f"{name}, adaptive (error_indicator, fraction {arguments.fraction:g}, 1->8)", adaptive,
              limit[(method, cell)])
        _, finest_dofs, finest_energy, finest_seconds = uniform[-1]
        reaching = [row for row in adaptive if row[2] <= finest_energy]
        if not reaching:
            print(f"{name}: no adaptive run reaches the finest uniform energy {finest_energy:.6f}")
            continue
        best = min(reaching, key=lambda row: row[3])
        print(f"{name}: the finest uniform run's error ({finest_dofs} DOFs, {finest_seconds:.2f} s) is reached "
              f"by '{best[0]}' with {best[1] / finest_dofs:.2f} of the DOFs and {best[3] / finest_seconds:.2f} "
              "of the time")
    plot(series, limit, out / "re_entrant_study.png")


if __name__ == "__main__":
    main()
