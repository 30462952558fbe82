#!/usr/bin/python3
"""Adaptive against uniform refinement, per method (issue #34; Martin et al. 2008 Fig. 6
in 3D): the bar of scenes/refine_bar.json (clamped, bending under its weight: the clamp's
edges are stress singularities) solved on uniform grids and by `refine` cycles from the
coarse grid, every run measured by `altfem compare` against one fine dg reference. Prints a
convergence table per method (error, DOFs, seconds, the rate against DOFs), then for each
method the cheapest adaptive run that reaches the finest uniform run's error, with its DOFs
and time as fractions of that run's, and plots error against DOFs and against seconds,
adaptive and uniform per method (refine_study.png in the output folder).

    /usr/bin/python3 bench/refine_study.py [--altfem build/bin/altfem] [--out out/refine_study]
        [--criterion error_indicator] [--threshold 5e3] [--cycles 3]
"""
import argparse
import csv
import json
import math
import pathlib
import subprocess

from study_plot import line_style, plot_error_against_cost

ROOT = pathlib.Path(__file__).resolve().parent.parent
UNIFORM = {"dg": [[9, 2, 2], [18, 4, 4]], "harmonic": [[9, 2, 2], [18, 4, 4], [36, 8, 8]],
           "fem": [[9, 2, 2], [18, 4, 4]]}
RESOLUTION_KEY = {"dg": "discretization/dg/resolution", "harmonic": "discretization/harmonic/convert/resolution",
                  "fem": "discretization/fem/resolution"}
REFERENCE = {"method": "dg", "set": {"discretization/dg/resolution": [36, 8, 8], "events": []}}


def compare(scene, out, altfem):
    """Runs `altfem compare` on `scene` (a dict) into `out`; returns results.csv's rows."""
    out.mkdir(parents=True, exist_ok=True)
    path = out / "scene.json"
    path.write_text(json.dumps(scene, indent=1))
    subprocess.run([altfem, "compare", str(path), "--out", str(out)], check=True)
    with open(out / "results.csv") as table:
        return [row for row in csv.DictReader(table) if row["status"] == "ok" and row["is_reference"] == "0"]


def table(title, rows, error="relative_rms_error"):
    """A convergence table of `rows` (results.csv's) by the column `error`."""
    print(f"\n{title}")
    print(f"{'run':44} {'DOFs':>8} {'error':>10} {'time [s]':>9} {'rate':>6}")
    previous = None
    for row in rows:
        dofs, value = int(row["dofs"]), float(row[error])
        # error ~ DOFs^(-rate/3): the rate in h of a 3D mesh.
        rate = "" if previous is None or dofs == previous[0] else \
            f"{-3 * math.log(value / previous[1]) / math.log(dofs / previous[0]):6.2f}"
        print(f"{row['label'][:44]:44} {dofs:8d} {value:10.3e} {float(row['total_s']):9.3f} {rate:>6}")
        previous = (dofs, value)


def report_reaching(method, uniform_series, adaptive_series, error="relative_rms_error"):
    """Prints the cheapest adaptive run that reaches the finest uniform run's error (the
    column `error`), with its DOFs and time as fractions of that run's (issue #34's target:
    <= 1/3 and <= 1/2)."""
    finest = uniform_series[-1]
    target = float(finest[error])
    reaching = [r for r in adaptive_series if float(r[error]) <= target]
    if not reaching:
        print(f"{method}: no adaptive run reaches the finest uniform error {target:.3e}")
        return
    best = min(reaching, key=lambda r: float(r["total_s"]))
    print(f"{method}: the finest uniform error {target:.3e} ({finest['dofs']} DOFs, {float(finest['total_s']):.3f} s) "
          f"reached by '{best['label']}' with {int(best['dofs']) / int(finest['dofs']):.2f} of the DOFs and "
          f"{float(best['total_s']) / float(finest['total_s']):.2f} of the time")


def plot(series, path, title="refine_bar: adaptive against uniform refinement", error="relative_rms_error",
         ylabel="RMS surface error / RMS displacement"):
    """Error (the column `error`) against DOFs and against seconds, a uniform and an
    adaptive line per method."""
    lines = {}
    for (method, kind), rows in series.items():
        color = {"dg": "C0", "harmonic": "C1", "fem": "C2"}.get(method, "C3")
        points = [(int(r["dofs"]), float(r["total_s"]), float(r[error])) for r in rows]
        lines[f"{method} {kind}"] = (line_style(kind == "uniform", color), points)
    plot_error_against_cost(lines, ylabel, title, path)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--altfem", default=str(ROOT / "build/bin/altfem"))
    parser.add_argument("--out", default=str(ROOT / "out/refine_study"))
    parser.add_argument("--criterion", default="error_indicator", choices=["error_indicator", "principal_stress"])
    parser.add_argument("--threshold", type=float, default=5e3)
    parser.add_argument("--split", default="1to8", choices=["1to8", "1to2"])
    parser.add_argument("--cycles", type=int, default=3)
    arguments = parser.parse_args()
    base = json.loads((ROOT / "scenes/refine_bar.json").read_text())
    out = pathlib.Path(arguments.out)

    uniform = dict(base, events=[])
    uniform["compare"] = {"methods": list(UNIFORM), "reference": REFERENCE,
                          "sweeps": {RESOLUTION_KEY[m]: UNIFORM[m] for m in UNIFORM}}
    adaptive = dict(base)
    adaptive["events"] = [{"time": 0, "refine": {"criterion": arguments.criterion, "threshold": arguments.threshold,
                                                 "split": arguments.split, "max_level": arguments.cycles,
                                                 "cycles": 1}}]
    adaptive["compare"] = {"methods": list(UNIFORM), "reference": REFERENCE,
                           "sweeps": {"events/0/refine/cycles": list(range(1, arguments.cycles + 1))}}
    uniform_rows = compare(uniform, out / "uniform", arguments.altfem)
    adaptive_rows = compare(adaptive, out / "adaptive", arguments.altfem)

    print(f"\nrefine_bar: uniform grids against {arguments.criterion} > {arguments.threshold:g} Pa, "
          f"{arguments.split}, 1-{arguments.cycles} cycles; error: RMS surface error / RMS displacement "
          "against dg k = 2 on 36x8x8")
    series = {}
    for method in UNIFORM:
        by_dofs = lambda rows: sorted((r for r in rows if r["method"] == method), key=lambda r: int(r["dofs"]))
        uniform_series, adaptive_series = by_dofs(uniform_rows), by_dofs(adaptive_rows)
        series[(method, "uniform")], series[(method, "adaptive")] = uniform_series, adaptive_series
        table(f"{method}, uniform", uniform_series)
        table(f"{method}, adaptive", adaptive_series)
        report_reaching(method, uniform_series, adaptive_series)
    plot(series, out / "refine_study.png")


if __name__ == "__main__":
    main()
