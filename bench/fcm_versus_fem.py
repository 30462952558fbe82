#!/usr/bin/python3
"""Longva et al. 2020's two performance comparisons (issue #17), medians over repeated runs
of `altfem run`, as ratios of FCM to fem measured in the same invocation:

1. The twisting hollow cylinder (scenes/twisting_cylinder.json, 25 steps) at equal surface
   error: Hex20 FCM 3x3x12 (RMS 5.3e-5) against Tet10 fem h = 0.12 (1.2e-4), the cheapest
   configurations of each that reach RMS <= 1.2e-4 in the scene's compare report
   (`altfem compare scenes/twisting_cylinder.json`); Hex8 FCM and Tet4 fem, which do not
   reach it, at their finest. Time per step and per Newton iteration (assembly and linear
   algebra). The paper: 359 ms (Hex20 FCM) vs 560 ms (Tet10 FEM) per step, 0.64x.
2. PCG on the armadillo slingshot (scenes/armadillo_slingshot.json, 5 steps) at two
   resolutions: Tet10 FCM with Additive-Schwarz against Tet10 fem with Jacobi, PCG
   iterations per Newton iteration and time per step. The paper: FCM within 1.25x of FEM's
   iterations.

Usage: bench/fcm_versus_fem.py [--altfem build/bin/altfem] [--repetitions 3]
"""
import argparse
import json
import statistics
import subprocess
import tempfile

CYLINDER = [
    ("fcm hex20 3x3x12", "fcm", ["discretization/fcm/cell=hex20", "discretization/fcm/resolution=[3,3,12]"]),
    ("fem tet10 h=0.12", "fem", ["discretization/fem/element=tet10", "discretization/fem/max_cell_size=0.12"]),
    ("fcm hex8 4x4x16", "fcm", ["discretization/fcm/cell=hex8", "discretization/fcm/resolution=[4,4,16]"]),
    ("fem tet4 h=0.12", "fem", ["discretization/fem/element=tet4", "discretization/fem/max_cell_size=0.12"]),
]
ARMADILLO = [
    ("fcm tet10 6x9x6", "fcm", ["discretization/fcm/resolution=[6,9,6]"]),
    ("fem tet10 h=0.15", "fem", ["discretization/fem/max_cell_size=0.15"]),
    ("fcm tet10 8x12x8", "fcm", ["discretization/fcm/resolution=[8,12,8]"]),
    ("fem tet10 h=0.12", "fem", ["discretization/fem/max_cell_size=0.12"]),
]


def measure(altfem, scene, method, settings, repetitions):
    """Medians of ms per step, ms per Newton iteration and linear iterations per Newton iteration."""
    per_step, per_iteration, linear = [], [], []
    for _ in range(repetitions):
        with tempfile.TemporaryDirectory() as out:
            command = [altfem, "run", scene, "--method", method, "--out", out]
            for setting in settings:
                command += ["--set", setting]
            subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
            with open(f"{out}/summary.json") as stream:
                summary = json.load(stream)
        timings = summary["timings_s"]
        seconds = sum(timings[k] for k in ("assembly", "analysis", "factorisation", "solve"))
        iterations = summary["newton_iterations"]
        per_step.append(1000 * seconds / summary["steps"])
        per_iteration.append(1000 * seconds / iterations)
        linear.append(summary["linear_iterations"] / iterations)
    return summary["dofs"], statistics.median(per_step), statistics.median(per_iteration), statistics.median(linear)


def study(title, altfem, scene, settings_extra, configurations, repetitions):
    print(title)
    print(f"  {'configuration':20s} {'DOFs':>7s} {'ms/step':>9s} {'ms/Newton':>10s} {'linear/Newton':>14s}")
    rows = {}
    for label, method, settings in configurations:
        rows[label] = measure(altfem, scene, method, settings + settings_extra, repetitions)
        dofs, step, iteration, linear = rows[label]
        print(f"  {label:20s} {dofs:7d} {step:9.1f} {iteration:10.1f} {linear:14.0f}")
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--altfem", default="build/bin/altfem")
    parser.add_argument("--repetitions", type=int, default=3)
    args = parser.parse_args()

    cylinder = study("Twisting cylinder, 25 steps (medians of %d runs)" % args.repetitions, args.altfem,
                     "scenes/twisting_cylinder.json", [], CYLINDER, args.repetitions)
    ratio = cylinder["fcm hex20 3x3x12"][1] / cylinder["fem tet10 h=0.12"][1]
    print(f"  Hex20 FCM / Tet10 fem time per step at equal error: {ratio:.2f} (paper 0.64, target <= 0.5)")

    armadillo = study("Armadillo slingshot, PCG, 5 steps (medians of %d runs)" % args.repetitions, args.altfem,
                      "scenes/armadillo_slingshot.json", ["time/steps=5"], ARMADILLO, args.repetitions)
    for fcm, fem in (("fcm tet10 6x9x6", "fem tet10 h=0.15"), ("fcm tet10 8x12x8", "fem tet10 h=0.12")):
        print(f"  {fcm} / {fem}: PCG iterations per Newton iteration {armadillo[fcm][3] / armadillo[fem][3]:.2f} "
              f"(paper <= 1.25), time per step {armadillo[fcm][1] / armadillo[fem][1]:.2f}")


if __name__ == "__main__":
    main()
