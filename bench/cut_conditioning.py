#!/usr/bin/python3
"""Conditioning across cut volume fractions (issue #33): a blade moved towards a face.

The 1 x 0.1 x 0.1 m bar held at both ends (bench/scenes/cut_bar.json: cells 0.1 m long
in every method) is cut through by the plane x = 0.6 - f * 0.1 before its static solve,
so the cell [0.5, 0.6] leaves a piece of volume fraction f on the right, joined to the
cell beyond. PCG solves the static system with each method's own remedy for small
pieces: fcm its stabilisation (alpha = 1e-6) and Additive-Schwarz blocks for cut cells
(its defaults), fem the same cells unstabilised (the virtual node algorithm keeps every
piece) with Jacobi, and with its remedy (cut_stabilization = 1e-6, fcm's alpha on its
cut elements), dg its block Jacobi, harmonic Jacobi. The table gives PCG iterations
to the relative residual 1e-10 and their ratio to the uncut bar's (issue #33's bar: at
most 10x); a run that fails says so (exit 3: PCG did not converge in 10,000).

Usage: bench/cut_conditioning.py [--altfem build/bin/altfem]
"""
import argparse
import json
import os
import subprocess
import tempfile

FRACTIONS = [1e-1, 1e-3, 1e-5, 1e-7, 1e-9]
# (the table's label, the method, its settings)
METHODS = [("fem", "fem", []), ("fem, cut_stabilization 1e-6", "fem", ["discretization/fem/cut_stabilization=1e-6"]),
           ("fcm", "fcm", []), ("dg", "dg", []), ("harmonic", "harmonic", [])]
SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes", "cut_bar.json")


def run(altfem, method, settings, fraction):
    """PCG iterations of the static solve after the cut, or the failure's first line."""
    events = "[]"
    if fraction is not None:
        x = 0.6 - fraction * 0.1
        events = '[{"time": 0, "cut": {"plane": {"point": [%.17g, 0, 0], "normal": [1, 0, 0]}}}]' % x
    with tempfile.TemporaryDirectory() as out:
        command = [altfem, "run", SCENE, "--method", method, "--out", out, "--set", "events=" + events]
        for setting in settings:
            command += ["--set", setting]
        result = subprocess.run(command, capture_output=True, text=True)
        if result.returncode != 0:
            return None, (result.stderr.strip().splitlines() or ["exit %d" % result.returncode])[0]
        with open(os.path.join(out, "summary.json")) as stream:
            return json.load(stream)["linear_iterations"], ""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--altfem", default="build/bin/altfem")
    arguments = parser.parse_args()
    print("| method | uncut | " + " | ".join("f = %.0e" % f for f in FRACTIONS) + " | worst / uncut |")
    print("|---|---|" + "---|" * len(FRACTIONS) + "---|")
    failures = []
    for label, method, settings in METHODS:
        uncut, problem = run(arguments.altfem, method, settings, None)
        if uncut is None:
            print("| %s | failed: %s |" % (label, problem))
            continue
        cells, worst = [], 0.0
        for fraction in FRACTIONS:
            iterations, problem = run(arguments.altfem, method, settings, fraction)
            if iterations is None:
                cells.append("failed")
                failures.append("%s at f = %.0e: %s" % (label, fraction, problem))
                worst = float("inf")
            else:
                cells.append(str(iterations))
                worst = max(worst, iterations / uncut)
        print("| %s | %d | %s | %s |" % (label, uncut, " | ".join(cells), "%.1fx" % worst))
    for failure in failures:
        print("- " + failure)


if __name__ == "__main__":
    main()
