#!/usr/bin/python3
"""One process against two (issue #37, step 2; docs/scaling.md): `altfem run` and
`mpirun -n 2 altfem run` of the same static scene with PETSc's CG + GAMG, one OpenMP
thread per process, so that the second process is the only added worker. Per phase
(assembly, the preconditioner's set-up, the CG solve, the whole run) the median of
--repetitions runs and the parallel efficiency T1 / (2 T2); per rank the peak resident
memory (from /usr/bin/time) in bytes per DOF of the whole problem, since the mesh, the
vectors and the assembled matrix are replicated on every rank. The two processes share
one machine's memory bandwidth, which bounds what the solve can gain here.

    /usr/bin/python3 bench/rank_scaling.py [--altfem build/bin/altfem] [--repetitions 3]
"""
import argparse
import json
import os
import pathlib
import re
import statistics
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
PROBLEMS = [
    # 541,059 DOFs: 270k per rank on two.
    ("fem hex20 cantilever [160,16,16]", "fem", ROOT / "scenes/cantilever.json",
     ["discretization/fem/element=hex20", "discretization/fem/resolution=[160,16,16]"]),
]
PHASES = [("assembly", lambda t: t["assembly"]), ("GAMG set-up", lambda t: t["analysis"] + t["factorisation"]),
          ("CG solve", lambda t: t["solve"]), ("whole run", lambda t: t["total"])]


def run(altfem, ranks, scene, method, settings, out):
    """The summary and every rank's peak resident set in bytes."""
    environment = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
                       OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    command = ["/usr/bin/time", "-f", "peak_kb %M", str(altfem), "run", str(scene), "--method", method,
               "--out", str(out), "--set", "solver/linear=petsc", "--set", "solver/linear_tolerance=1e-8",
               "--set", "output/volume=false"]
    for setting in settings:
        command += ["--set", setting]
    if ranks > 1:
        command = ["mpirun", "-n", str(ranks), "--oversubscribe"] + command
    finished = subprocess.run(command, capture_output=True, text=True, env=environment)
    if finished.returncode != 0:
        raise SystemExit(f"{' '.join(command)} failed: {finished.stderr.strip()}")
    peaks = [1024 * int(kb) for kb in re.findall(r"peak_kb (\d+)", finished.stderr)]
    return json.loads((out / "summary.json").read_text()), peaks


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--altfem", default=ROOT / "build/bin/altfem")
    parser.add_argument("--repetitions", type=int, default=3)
    arguments = parser.parse_args()
    print("| problem | DOFs | phase | 1 rank s | 2 ranks s | T1/(2 T2) |")
    print("|---|---:|---|---:|---:|---:|")
    memory = []
    with tempfile.TemporaryDirectory() as folder:
        for label, method, scene, settings in PROBLEMS:
            timings = {1: [], 2: []}
            peaks = {1: [], 2: []}
            for repetition in range(arguments.repetitions):
                for ranks in (1, 2):  # interleaved, so that a change in the machine's load hits both
                    summary, peak = run(arguments.altfem, ranks, scene, method, settings,
                                        pathlib.Path(folder) / f"{ranks}-{repetition}")
                    timings[ranks].append(summary["timings_s"])
                    peaks[ranks].append(max(peak) if peak else 0)
                    dofs = summary["dofs"]
                    iterations = summary["linear_iterations"]
                    print(f"<!-- {label}: {ranks} rank(s), repetition {repetition}: {iterations} CG iterations -->",
                          flush=True)
            for phase, seconds_of in PHASES:
                one = statistics.median(seconds_of(t) for t in timings[1])
                two = statistics.median(seconds_of(t) for t in timings[2])
                print(f"| {label} | {dofs:,} | {phase} | {one:.2f} | {two:.2f} | {one / (2 * two):.2f} |", flush=True)
            memory.append((label, dofs, statistics.median(peaks[1]), statistics.median(peaks[2])))
    print("\n| problem | DOFs | peak memory, 1 rank | per rank, 2 ranks | bytes per DOF per rank (2 ranks) |")
    print("|---|---:|---:|---:|---:|")
    for label, dofs, one, two in memory:
        print(f"| {label} | {dofs:,} | {one / 2**30:.2f} GiB | {two / 2**30:.2f} GiB | {two / dofs:,.0f} |")


if __name__ == "__main__":
    main()
