#!/usr/bin/python3
"""Draws report.md and its PNG plots from an `altfem compare` results.csv alone.

Usage: scripts/plot_report.py RESULTS.csv [--out DIR] [--error E]
  --out    folder for report.md and the PNGs (default: the folder of RESULTS.csv)
  --error  the error of the equal-accuracy table, in the measure the report ranks by
           (default: the scene's compare/error, kept in results.csv's report_error
           column, else the smallest error every method series reaches, i.e. the largest
           of their minima)

The report ranks by an error relative to the solution, never to the body's size: the
relative L2 error against the scene's exact solution when every run has one, else the RMS
surface error over the reference's RMS displacement (docs/conventions.md, "Metrics").
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PHASES = ["setup_s", "quadrature_s", "assembly_s", "analysis_s", "factorisation_s", "solve_s"]  # results.csv columns


def number(text):
    return float(text) if text not in ("", None) else math.nan


def read_rows(path):
    with open(path, newline="") as stream:
        rows = list(csv.DictReader(stream))
    for row in rows:
        for key in ("dofs", "elements", "quadrature_points", "steps", "newton_iterations", "linear_iterations",
                    "exit_code", "total_s", "wall_s", "peak_memory_mib", "rms_error", "max_error", *PHASES):
            row[key] = number(row[key])
        for key in ("report_error", "relative_rms_error", "field_l2_error", "field_h1_error", "events",
                    "refinements", *EVENT_PHASES):  # absent from older tables
            row[key] = number(row.get(key))
    # A run that refined is adaptive: its own series beside the method's uniform runs. Its
    # elements are those it ended with, which refinement may change (harmonic's hexahedra
    # become polyhedra when split): a mix no uniform run of its method has takes the
    # element of those runs when they share one, so that its cycles form one series.
    uniform_elements = {}
    for row in rows:
        if not (row["refinements"] and row["refinements"] > 0):
            uniform_elements.setdefault(row["method"], set()).add(row["element"])
    for row in rows:
        adaptive = row["refinements"] and row["refinements"] > 0
        element = row["element"]
        uniform = uniform_elements.get(row["method"], set())
        if adaptive and element not in uniform and len(uniform) == 1:
            element = next(iter(uniform))
        row["series"] = f"{row['method']} {element}".strip() + (" adaptive" if adaptive else "")
    return rows


class Measure:
    """The error the report ranks by: a results.csv column and how the report names it."""

    def __init__(self, column, name, axis, against_reference):
        self.column, self.name, self.axis = column, name, axis
        self.against_reference = against_reference  # the reference run's own error is 0 by definition


FIELD_ERROR = Measure("field_l2_error", "the relative L2 error against the exact solution",
                      "relative L2 error ||u_h - u|| / ||u|| [-]", False)
RELATIVE_SURFACE_ERROR = Measure("relative_rms_error",
                                 "the RMS surface error relative to the reference's RMS displacement",
                                 "RMS surface error / RMS reference displacement [-]", True)
DIAGONAL_SURFACE_ERROR = Measure("rms_error", "the RMS surface error relative to the bounding-box diagonal",
                                 "RMS surface error / bounding-box diagonal [-]", True)


def ranking_measure(rows):
    """The field error where every successful run has one (an exact solution), else the
    surface error relative to the solution; a table from before that column: the diagonal."""
    ok = [r for r in rows if r["status"] == "ok"]
    if ok and all(r["field_l2_error"] > 0 for r in ok):
        return FIELD_ERROR
    if any(not math.isnan(r["relative_rms_error"]) for r in ok):
        return RELATIVE_SURFACE_ERROR
    return DIAGONAL_SURFACE_ERROR


def measured(rows, measure):
    """Successful runs with a finite positive error in `measure` (kept in row["error"]);
    the reference too when the measure does not compare against it."""
    runs = []
    for r in rows:
        if r["status"] != "ok" or (measure.against_reference and r["is_reference"] == "1"):
            continue
        if 0 < r[measure.column] < math.inf:
            runs.append(dict(r, error=r[measure.column]))
    return runs


def pareto_front(rows):
    """Runs no other run beats in both wall time and error, sorted by time."""
    front, best = [], math.inf
    for row in sorted(rows, key=lambda r: (r["total_s"], r["error"])):
        if row["error"] < best:
            front.append(row)
            best = row["error"]
    return front


def series_of(rows):
    groups = {}
    for row in rows:
        groups.setdefault(row["series"], []).append(row)
    return groups


def series_styles(names):
    """A colour per method and element, solid for uniform runs and dashed for the adaptive
    series of the same method and element, so the two read as a pair."""
    bases = sorted({name.removesuffix(" adaptive") for name in names})
    colours = {base: f"C{k % 10}" for k, base in enumerate(bases)}
    return {name: dict(color=colours[name.removesuffix(" adaptive")],
                       linestyle="--" if name.endswith(" adaptive") else "-",
                       marker="s" if name.endswith(" adaptive") else "o") for name in names}


def finish_error_plot(fig, ax, path, xlabel, title, legend_title, ylabel):
    """Labels, grid and legend (outside, so it hides no point) of a log-log error plot; saves it."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(title=legend_title, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.savefig(path, dpi=110, bbox_inches="tight")  # the legend outside stays in the picture
    plt.close(fig)


def plot_error_vs_time(rows, path, measure):
    fig, ax = plt.subplots(figsize=(9, 5))
    series = series_of(rows)
    styles = series_styles(series)
    for name, group in sorted(series.items()):
        group = sorted(group, key=lambda r: r["dofs"])  # the line follows refinement
        ax.loglog([r["total_s"] for r in group], [r["error"] for r in group], label=name, **styles[name])
    front = pareto_front(rows)
    ax.loglog([r["total_s"] for r in front], [r["error"] for r in front], "k--", lw=1, zorder=0,
              drawstyle="steps-post", label="Pareto front (circled runs:\nnone other is both faster\nand more accurate)")
    ax.scatter([r["total_s"] for r in front], [r["error"] for r in front], s=140, facecolors="none",
               edgecolors="k", zorder=3)
    finish_error_plot(fig, ax, path, "wall time of the run, total [s]", "Accuracy against cost (lower left is better)",
                      "method, element", measure.axis)


def fitted_rate(group, key):
    """Slope of log(error) against log(DOFs^(1/3)) (error ~ h^rate, h ~ DOFs^(-1/3))."""
    if len(group) < 2:
        return None
    h = np.array([r["dofs"] for r in group]) ** (-1.0 / 3.0)
    e = np.array([r[key] for r in group])
    return float(np.polyfit(np.log(h), np.log(e), 1)[0])


def plot_error_vs_dofs(rows, path, key, ylabel, title="Convergence: error against DOFs (h ~ DOFs^(-1/3))"):
    fig, ax = plt.subplots(figsize=(9, 5))
    rates = {}
    series = series_of(rows)
    styles = series_styles(series)
    for name, group in sorted(series.items()):
        group = sorted(group, key=lambda r: r["dofs"])
        rate = fitted_rate(group, key)
        rates[name] = rate
        label = name + (f" (rate {rate:.2f} in h)" if rate is not None else "")
        ax.loglog([r["dofs"] for r in group], [r[key] for r in group], label=label, **styles[name])
    finish_error_plot(fig, ax, path, "degrees of freedom [-]", title, "method, element (fitted rate)", ylabel)
    return rates


def field_error_section(rows, out):
    """Errors against the scene's exact_displacement (every successful run, the reference too)."""
    exact = [r for r in rows if r["status"] == "ok" and r["field_l2_error"] > 0 and r["field_h1_error"] > 0]
    if not exact:
        return []
    l2_rates = plot_error_vs_dofs(exact, os.path.join(out, "field_l2_vs_dofs.png"), "field_l2_error",
                                  "relative L2 error ||u_h - u|| / ||u|| [-]",
                                  "Exact solution: L2 error against DOFs (h ~ DOFs^(-1/3))")
    h1_rates = plot_error_vs_dofs(exact, os.path.join(out, "field_h1_vs_dofs.png"), "field_h1_error",
                                  "relative H1-seminorm error |u_h - u| / |u| [-]",
                                  "Exact solution: H1-seminorm error against DOFs (h ~ DOFs^(-1/3))")
    lines = ["| run | DOFs | L2 error | H1 error | total [s] |", "|---|---|---|---|---|"]
    for r in sorted(exact, key=lambda r: (r["series"], r["dofs"])):
        lines.append(f"| {r['label']} | {r['dofs']:.0f} | {r['field_l2_error']:.3g} | {r['field_h1_error']:.3g} | "
                     f"{r['total_s']:.3g} |")
    rates = ", ".join(f"{name} L2 {l2_rates[name]:.2f}, H1 {h1_rates[name]:.2f}"
                      for name in sorted(l2_rates) if l2_rates[name] is not None)
    return ["## Field errors against the exact solution", "",
            "Relative errors of each run's displacement field against the scene's `exact_displacement`, "
            "by the method's own basis and quadrature (summary.json's `field_errors`).", "",
            "![L2 error against DOFs](field_l2_vs_dofs.png)", "", "![H1 error against DOFs](field_h1_vs_dofs.png)", "",
            "\n".join(lines), "", "Fitted rates (error ~ h^rate): " + (rates or "one run per series"), ""]


EVENT_PHASES = ("event_geometry_s", "event_integration_s", "event_pattern_s", "event_transfer_s")


def event_section(rows, measure):
    """What the scene's events (cuts, releases) cost each run, beside its error at the end, after them."""
    with_events = [r for r in rows if r["status"] == "ok" and r["events"] > 0]
    if not with_events:
        return []
    lines = ["| run | events | geometry [s] | integration [s] | pattern [s] | transfer [s] | events / total | "
             f"error at the end |", "|---|---|---|---|---|---|---|---|"]
    for r in sorted(with_events, key=lambda r: (r["series"], r["dofs"])):
        spent = sum(r[key] for key in EVENT_PHASES)
        error = r[measure.column] if measure else math.nan
        lines.append(f"| {r['label']} | {r['events']:.0f} | " + " | ".join(f"{r[key]:.3g}" for key in EVENT_PHASES) +
                     f" | {spent / r['total_s']:.1%} | {'' if math.isnan(error) else f'{error:.3g}'} |")
    return ["## Events", "",
            "The scene's events per run (summary.json's `events`): wall seconds per phase summed over them — "
            "geometry (cutting the mesh), integration (the rebuilt method), pattern (sparsity and solver), "
            "transfer (the state) — and the run's error at its end, after them.", "", "\n".join(lines), ""]


def phase_times(row):
    """Seconds per phase; summary.json's setup includes the quadrature, shown apart here."""
    phases = {"setup (scene, mesh, basis)": max(row["setup_s"] - row["quadrature_s"], 0.0),
              "quadrature": row["quadrature_s"], "assembly": row["assembly_s"], "analysis": row["analysis_s"],
              "factorisation": row["factorisation_s"], "solve": row["solve_s"]}
    phases = {name: max(value, 0.0) for name, value in phases.items()}
    phases["other (output, Newton bookkeeping)"] = max(row["total_s"] - sum(phases.values()), 0.0)
    return phases


def plot_time_breakdown(rows, path):
    ok = [r for r in rows if r["status"] == "ok"]
    fig, ax = plt.subplots(figsize=(10, 0.35 * len(ok) + 2.0))
    labels = [r["label"] + (" (reference)" if r["is_reference"] == "1" else "") for r in ok]
    left = np.zeros(len(ok))
    for phase in phase_times(ok[0]):
        share = np.array([100.0 * phase_times(r)[phase] / max(r["total_s"], 1e-12) for r in ok])
        ax.barh(labels, share, left=left, label=phase)
        left += share
    for i, r in enumerate(ok):
        ax.text(101, i, f"{r['total_s']:.3g} s", va="center", fontsize="small")
    ax.set_xlim(0, 122)
    ax.set_xlabel("share of the run's total wall time [%] (total at the right of each bar)")
    ax.set_title("Where the time goes, per run")
    ax.invert_yaxis()
    ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.0, 1.0))
    fig.savefig(path, dpi=110, bbox_inches="tight")  # long labels and the legend stay in the picture
    plt.close(fig)


def default_target(rows):
    """The smallest error every series reaches: the largest of the series' minima."""
    minima = [min(r["error"] for r in group) for group in series_of(rows).values()]
    return max(minima) if minima else math.nan


def solve_seconds(row):
    """The time spent stepping: assembly and linear algebra, without set-up and quadrature."""
    return sum(row[key] for key in ("assembly_s", "analysis_s", "factorisation_s", "solve_s"))


def per_step_ms(row):
    return f"{1000 * solve_seconds(row) / row['steps']:.3g}" if row["steps"] > 0 else "—"


def per_iteration_ms(row):
    iterations = row["newton_iterations"]
    return f"{1000 * solve_seconds(row) / iterations:.3g}" if iterations > 0 else "—"


def cheapest_per_series(rows, target):
    """Per series: the cheapest run with error <= target, sorted by time."""
    best = {}
    for name, group in series_of(rows).items():
        good = [r for r in group if r["error"] <= target]
        if good:
            best[name] = min(good, key=lambda r: r["total_s"])
    return dict(sorted(best.items(), key=lambda item: item[1]["total_s"]))


def findings(rows, target, measure):
    """The report's opening two sentences, read off the equal-accuracy table."""
    best = cheapest_per_series(rows, target)
    if not best:
        return f"No run reaches {measure.name} ≤ {target:.3g}."
    series = list(best)
    winner = best[series[0]]
    first = f"At {measure.name} ≤ {target:.3g}, the cheapest run is {series[0]} ({winner['label']}, " \
            f"{winner['total_s']:.3g} s)"
    rivals = [name for name in series if best[name]["method"] != winner["method"]]
    if rivals:
        rival = best[rivals[0]]
        first += f", {rival['total_s'] / winner['total_s']:.1f}× faster than the cheapest other method, " \
                 f"{rivals[0]} ({rival['total_s']:.3g} s)."
    else:
        first += "; no other method reaches that accuracy."
    missing = sorted(set(series_of(rows)) - set(best))
    second = f"{len(best)} of {len(best) + len(missing)} method–element series reach it"
    second += f"; {', '.join(missing)} {'does' if len(missing) == 1 else 'do'} not." if missing else "."
    return first + " " + second


def equal_accuracy_table(rows, target):
    """Per series: the cheapest run with error <= target, and its time relative to the fastest."""
    best = cheapest_per_series(rows, target)
    fastest = min((r["total_s"] for r in best.values()), default=math.nan)
    lines = ["| method, element | cheapest configuration | DOFs | error | RMS surface error / diagonal | "
             "total time [s] | per step [ms] | per Newton iteration [ms] | relative to the fastest |",
             "|---|---|---|---|---|---|---|---|---|"]
    for name, r in best.items():
        lines.append(f"| {name} | {r['label']} | {int(r['dofs'])} | {r['error']:.3g} | {r['rms_error']:.3g} | "
                     f"{r['total_s']:.3g} | {per_step_ms(r)} | {per_iteration_ms(r)} | "
                     f"{r['total_s'] / fastest:.1f}× |")
    missing = sorted(set(series_of(rows)) - set(best))
    if missing:
        lines.append("")
        lines.append("Not reached by: " + ", ".join(missing) + ".")
    return "\n".join(lines)


def run_table(rows):
    lines = ["| run | status | exit | DOFs | elements | quadrature points | Newton | linear | total [s] | "
             "peak memory [MiB] | RMS surface error / RMS displacement | RMS / diagonal | max / diagonal |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]

    def cell(value, fmt):
        return "—" if math.isnan(value) else format(value, fmt)

    for r in rows:
        name = r["label"] + (" **(reference)**" if r["is_reference"] == "1" else "")
        lines.append(f"| {name} | {r['status']} | {int(r['exit_code'])} | {cell(r['dofs'], '.0f')} | "
                     f"{cell(r['elements'], '.0f')} | {cell(r['quadrature_points'], '.0f')} | "
                     f"{cell(r['newton_iterations'], '.0f')} | {cell(r['linear_iterations'], '.0f')} | "
                     f"{cell(r['total_s'], '.3g')} | {cell(r['peak_memory_mib'], '.0f')} | "
                     f"{cell(r['relative_rms_error'], '.3g')} | {cell(r['rms_error'], '.3g')} | "
                     f"{cell(r['max_error'], '.3g')} |")
    return "\n".join(lines)


def write_report(rows, out, target_arg):
    os.makedirs(out, exist_ok=True)
    first = rows[0]
    measure = ranking_measure(rows)
    runs = measured(rows, measure)
    reference = [r for r in rows if r["is_reference"] == "1"]
    text = [f"# altfem compare: {first['scene']}", ""]
    if runs:
        scene_targets = [r["report_error"] for r in rows if not math.isnan(r["report_error"])]
        target = target_arg if target_arg is not None else scene_targets[0] if scene_targets else default_target(runs)
        text += [findings(runs, target, measure), ""]
    text += [f"- **Scene:** `{first['scene']}`",
             f"- **Machine:** {first['cpu']}, {first['cores']} cores, {first['threads']} thread(s) per run, "
             f"BLAS {first['blas']}",
             f"- **Date:** {first['date']}",
             f"- **Runs:** {len(rows)} ({sum(r['status'] == 'ok' for r in rows)} ok, "
             f"{sum(r['status'] != 'ok' for r in rows)} failed)",
             f"- **Reference:** {reference[0]['label'] if reference else 'none (no run succeeded)'}", "",
             f"Error, the report ranks by: {measure.name} (docs/conventions.md, \"Metrics\"). The surface error "
             "is the RMS over the embedded surface vertices of |x − x_reference|; over the bounding-box diagonal it "
             "is kept as a column. Time: the run's own total wall time.", ""]
    if runs:
        plot_error_vs_time(runs, os.path.join(out, "error_vs_time.png"), measure)
        rates = plot_error_vs_dofs(runs, os.path.join(out, "error_vs_dofs.png"), "error", measure.axis)
        text += ["## Accuracy against wall time", "", "![error against time](error_vs_time.png)", "",
                 f"## Equal accuracy: error ≤ {target:.3g}", "", equal_accuracy_table(runs, target), "",
                 "## Error against DOFs", "", "![error against DOFs](error_vs_dofs.png)", "",
                 "Fitted rates (error ~ h^rate): " +
                 ", ".join(f"{name} {rate:.2f}" for name, rate in sorted(rates.items()) if rate is not None), ""]
    text += field_error_section(rows, out)
    text += event_section(rows, measure if runs else None)
    if any(r["status"] == "ok" for r in rows):
        plot_time_breakdown(rows, os.path.join(out, "time_breakdown.png"))
        text += ["## Time per phase", "", "![time breakdown](time_breakdown.png)", ""]
    text += ["## Every run", "", run_table(rows), ""]
    failed = [r for r in rows if r["status"] != "ok"]
    if failed:
        text += ["## Failed runs", ""]
        text += [f"- **{r['label']}**: {r['status']} (exit code {int(r['exit_code'])}): {r['message']}" for r in failed]
        text += [""]
    noted = [r for r in rows if r["status"] == "ok" and r["message"]]
    if noted:
        text += ["## Notes", ""] + [f"- {r['label']}: {r['message']}" for r in noted] + [""]
    with open(os.path.join(out, "report.md"), "w") as stream:
        stream.write("\n".join(text))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results")
    parser.add_argument("--out")
    parser.add_argument("--error", type=float)
    arguments = parser.parse_args()
    rows = read_rows(arguments.results)
    if not rows:
        sys.exit(f"{arguments.results}: no runs")
    write_report(rows, arguments.out or os.path.dirname(os.path.abspath(arguments.results)), arguments.error)


if __name__ == "__main__":
    main()
