#!/usr/bin/python3
"""Threads and a busy machine (issue #35): medians over repeated runs of `altfem run`, by phase.

Two goals, each checked and printed as PASS/FAIL:
1. More threads are never slower: OMP_NUM_THREADS = 1, 2, 4 on this machine give
   total times that do not grow (each within 10 % of the one before or faster).
2. One busy process beside a run (`sh -c 'while :; do :; done'`) costs at most 2x the
   idle time, at the default thread count.

With --peer PATH (another build of altfem, e.g. the one before the thread choices of
docs/conventions.md, "Threads"), the same cases run with that executable in the same
invocation and the table gives the ratios new / peer.

Usage: bench/thread_scaling.py [--altfem build/bin/altfem] [--peer OTHER/bin/altfem]
                               [--repetitions 3] [--threads 1,2,4]
       [--scene scenes/twisting_cylinder.json --method fcm --set time/steps=5 ...]
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile

PHASES = ("assembly", "factorisation", "solve", "total")


def run_once(altfem, scene, method, settings, environment):
    """The summary.json timings of one run, with `environment` added to this process's."""
    with tempfile.TemporaryDirectory() as out:
        command = [altfem, "run", scene, "--method", method, "--out", out]
        for setting in settings:
            command += ["--set", setting]
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       env={**os.environ, **environment})
        with open(os.path.join(out, "summary.json")) as summary_file:
            summary = json.load(summary_file)
    timings = summary["timings_s"]
    blas = summary["environment"].get("factorisation_blas_threads", {})
    return {phase: timings[phase] for phase in PHASES}, blas


def measure(altfem, arguments, threads, busy):
    """Medians per phase over the repetitions; `busy` starts a spinning process beside each run."""
    environment = {"OMP_NUM_THREADS": str(threads)} if threads else {}
    samples = {phase: [] for phase in PHASES}
    blas_threads = set()
    for _ in range(arguments.repetitions):
        spinner = subprocess.Popen(["sh", "-c", "while :; do :; done"]) if busy else None
        try:
            timings, blas = run_once(altfem, arguments.scene, arguments.method, arguments.set, environment)
        finally:
            if spinner:
                spinner.kill()
                spinner.wait()
        for phase in PHASES:
            samples[phase].append(timings[phase])
        if blas:
            blas_threads.add(f"{blas['fewest']}-{blas['most']}" if blas["fewest"] != blas["most"] else str(blas["most"]))
    return {phase: statistics.median(values) for phase, values in samples.items()}, ",".join(sorted(blas_threads))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--altfem", default="build/bin/altfem")
    parser.add_argument("--peer", help="another altfem executable measured in the same invocation")
    parser.add_argument("--repetitions", type=int, default=3)
    parser.add_argument("--threads", default="1,2,4")
    parser.add_argument("--scene", default="scenes/twisting_cylinder.json")
    parser.add_argument("--method", default="fcm")
    parser.add_argument("--set", action="append", default=None)
    arguments = parser.parse_args()
    if arguments.set is None:
        arguments.set = ["time/steps=5"]
    counts = [int(count) for count in arguments.threads.split(",")]
    executables = [("altfem", arguments.altfem)] + ([("peer", arguments.peer)] if arguments.peer else [])

    print(f"{arguments.scene} --method {arguments.method} --set {' --set '.join(arguments.set)}; "
          f"{os.cpu_count()} cores; medians of {arguments.repetitions} (s)")
    header = f"{'build':<7} {'case':<22}" + "".join(f"{phase:>14}" for phase in PHASES) + f"{'BLAS threads':>14}"
    print(header)
    results = {}
    cases = [(f"{count} thread{'s' if count > 1 else ''}, idle", count, False) for count in counts]
    cases.append(("default, one busy", 0, True))
    cases.insert(len(counts), ("default, idle", 0, False))
    for name, executable in executables:
        for case, threads, busy in cases:
            medians, blas = measure(executable, arguments, threads, busy)
            results[(name, case)] = medians
            print(f"{name:<7} {case:<22}" + "".join(f"{medians[phase]:>14.3f}" for phase in PHASES) + f"{blas:>14}",
                  flush=True)
    if arguments.peer:
        print("\nratios altfem / peer (total):")
        for case, _, _ in cases:
            print(f"  {case:<22} {results[('altfem', case)]['total'] / results[('peer', case)]['total']:.2f}")

    ok = True
    print()
    for name, _ in executables:
        totals = [results[(name, case)]["total"] for case, _, _ in cases[: len(counts)]]
        monotone = all(later <= 1.1 * earlier for earlier, later in zip(totals, totals[1:]))
        busy = results[(name, "default, one busy")]["total"] / results[(name, "default, idle")]["total"]
        print(f"{name}: threads {arguments.threads} -> totals "
              f"{', '.join(f'{total:.2f}' for total in totals)} s: {'PASS' if monotone else 'FAIL'} (never slower, 10 %)")
        print(f"{name}: one busy process beside the run: {busy:.2f}x idle: {'PASS' if busy <= 2 else 'FAIL'} (<= 2x)")
        if name == "altfem":
            ok = ok and monotone and busy <= 2
    raise SystemExit(0 if ok else 1)


if __name__ == "__main__":
    main()
