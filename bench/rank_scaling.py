#!/usr/bin/python3
"""One process against several (issue #37, step 2; docs/scaling.md): `altfem run` and
`mpirun -n N altfem run` of the same static scene with PETSc's CG + GAMG, one OpenMP
thread per process, so that each added process is the only added worker. Per phase
(assembly, the preconditioner's set-up, the CG solve, the whole run) the median of
--repetitions runs and the parallel efficiency T1 / (N TN); the largest rank's peak
resident memory in bytes per DOF of the whole problem (the mesh and the vectors are
replicated on every rank, the matrix is each rank's share). The processes share one
machine's memory bandwidth, which bounds what the solve can gain.

    /usr/bin/python3 bench/rank_scaling.py [--altfem build/bin/altfem] [--repetitions 3]
                                           [--ranks 1,2] [--mpirun mpirun] [--set KEY=VALUE]
"""
import argparse
import json
import os
import pathlib
import shlex
import statistics
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
PROBLEMS = [
    # 541,059 DOFs: 270k per rank on two.
    ("fem hex20 cantilever [160,16,16]", "fem", ROOT / "scenes/cantilever.json",
     ["discretization/fem/element=hex20", "discretization/fem/resolution=[160,16,16]"]),
]
PHASES = [("assembly", lambda t: t["assembly"]), ("GAMG set-up", lambda t: t["analysis"] + t["factorisation"]),
          ("CG solve", lambda t: t["solve"]), ("whole run", lambda t: t["total"])]
# Runs a command and reports the largest peak resident set among its descendants (with
# mpirun: the largest rank's), so no /usr/bin/time is needed.
PEAK_OF_DESCENDANTS = ("import resource, subprocess, sys; code = subprocess.run(sys.argv[1:]).returncode; "
                       "print('peak_kb', resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, file=sys.stderr); "
                       "sys.exit(code)")


def run(arguments, ranks, scene, method, settings, out):
    """The summary and the largest rank's peak resident set in bytes."""
    environment = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
                       OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    command = [str(arguments.altfem), "run", str(scene), "--method", method, "--out", str(out),
               "--set", "solver/linear=petsc", "--set", "solver/linear_tolerance=1e-8",
               "--set", "output/volume=false"]
    for setting in settings + arguments.set:
        command += ["--set", setting]
    if ranks > 1:
        command = shlex.split(arguments.mpirun) + ["-n", str(ranks), "--oversubscribe"] + command
    command = [sys.executable, "-c", PEAK_OF_DESCENDANTS] + command
    finished = subprocess.run(command, capture_output=True, text=True, env=environment)
    if finished.returncode != 0:
        raise SystemExit(f"{shlex.join(command)} failed: {finished.stderr.strip()}")
    peak_kb = int(finished.stderr.rsplit("peak_kb ", 1)[1].split()[0])
    return json.loads((out / "summary.json").read_text()), 1024 * peak_kb


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--altfem", default=ROOT / "build/bin/altfem")
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--ranks", default="1,2", help="process counts, the first the baseline")
    parser.add_argument("--mpirun", default="mpirun", help="the launcher, with any options of its own")
    parser.add_argument("--set", action="append", default=[], help="a setting added to every problem's, KEY=VALUE")
    arguments = parser.parse_args()
    counts = [int(count) for count in arguments.ranks.split(",")]
    base = counts[0]
    print("| problem | DOFs | phase | " + " | ".join(f"{n} rank{'s' if n > 1 else ''} s" for n in counts) + " | "
          + " | ".join(f"T{base}/({n // base} T{n})" for n in counts[1:]) + " |")
    print("|---|---:|---|" + "---:|" * (2 * len(counts) - 1))
    memory = []
    with tempfile.TemporaryDirectory() as folder:
        for label, method, scene, settings in PROBLEMS:
            label += "".join(f", {setting}" for setting in arguments.set)
            timings = {n: [] for n in counts}
            peaks = {n: [] for n in counts}
            for repetition in range(arguments.repetitions):
                for ranks in counts:  # interleaved, so that a change in the machine's load hits every count
                    summary, peak = run(arguments, ranks, scene, method, settings,
                                        pathlib.Path(folder) / f"{ranks}-{repetition}")
                    timings[ranks].append(summary["timings_s"])
                    peaks[ranks].append(peak)
                    dofs = summary["dofs"]
                    iterations = summary["linear_iterations"]
                    print(f"<!-- {label}: {ranks} rank(s), repetition {repetition}: {iterations} CG iterations, "
                          f"{summary['timings_s']['total']:.2f} s -->", flush=True)
            for phase, seconds_of in PHASES:
                medians = {n: statistics.median(seconds_of(t) for t in timings[n]) for n in counts}
                efficiencies = [medians[base] / (n / base * medians[n]) for n in counts[1:]]
                print(f"| {label} | {dofs:,} | {phase} | " + " | ".join(f"{medians[n]:.2f}" for n in counts) + " | "
                      + " | ".join(f"{efficiency:.2f}" for efficiency in efficiencies) + " |", flush=True)
            memory.append((label, dofs, {n: statistics.median(peaks[n]) for n in counts}))
    print("\n| problem | DOFs | ranks | largest rank's peak | bytes per DOF per rank |")
    print("|---|---:|---:|---:|---:|")
    for label, dofs, peak in memory:
        for n in counts:
            print(f"| {label} | {dofs:,} | {n} | {peak[n] / 2**30:.2f} GiB | {peak[n] / dofs:,.0f} |")


if __name__ == "__main__":
    main()
