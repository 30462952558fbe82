#!/usr/bin/env python3
"""The tables of scripts/bench-peers (issue #39): medians and altfem / deal.II ratios.

    peer_table.py RAW_FILE

RAW_FILE holds one line of key=value pairs per run (what scripts/bench-peers appends: the
case's keys, then what altfem_result.py or a peer program printed). Prints Markdown.
"""
import statistics
import sys
from collections import defaultdict


def read(path: str) -> list[dict[str, str]]:
    with open(path) as file:
        return [dict(pair.split("=", 1) for pair in line.split()) for line in file if "=" in line]


def median(runs: list[dict[str, str]], key: str) -> float:
    return statistics.median(float(run[key]) for run in runs)


def assembly_and_solve(runs: list[dict[str, str]]) -> float:
    return statistics.median(float(run["assembly_s"]) + float(run["solve_s"]) for run in runs)


def group(runs: list[dict[str, str]], *keys: str) -> dict[tuple, list[dict[str, str]]]:
    groups = defaultdict(list)
    for run in runs:
        groups[tuple(run.get(key, "") for key in keys)].append(run)
    return groups


def cantilever(runs: list[dict[str, str]]) -> None:
    runs = [run for run in runs if run["problem"] == "cantilever"]
    if not runs:
        return
    grid_size = lambda grid: [int(count) for count in grid.split(",")]
    finest = max((run["grid"] for run in runs), key=lambda grid: grid_size(grid)[0])
    reference_runs = [run for run in runs if run["grid"] == finest and run["degree"] == "2" and run["side"] == "altfem"
                      and run["solver"] == "direct"]
    reference = float(reference_runs[0]["tip_z"])
    cases = group(runs, "grid", "degree", "solver", "threads", "side")
    print(f"Cantilever: tip deflection w at (1, 0.05, 0.05); error against altfem Hex27 {finest} with CHOLMOD, "
          f"w = {reference:.7e} m. Times: medians of {min(map(len, cases.values()))} runs, s.\n")
    print("| grid | element | DOFs | solver altfem / deal.II | threads | wall altfem | wall deal.II | ratio "
          "| asm+solve altfem | asm+solve deal.II | ratio | CG iterations | w error altfem / deal.II |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    solver_names = {"direct": "CHOLMOD / UMFPACK", "iterative": "CG+GAMG / CG+ML AMG"}
    cases = group(runs, "grid", "degree", "solver", "threads")
    for (grid, degree, solver, threads) in sorted(cases, key=lambda case: (grid_size(case[0]), case[1], case[2], case[3])):
        sides = group(cases[(grid, degree, solver, threads)], "side")
        altfem, peer = sides.get(("altfem",)), sides.get(("dealii",))
        if not altfem or not peer:
            continue
        element = "Hex8 / Q1" if degree == "1" else "Hex27 / Q2"
        error = lambda side: abs(float(side[0]["tip_z"]) - reference) / abs(reference)
        iterations = f"{altfem[0]['iterations']} / {peer[0]['iterations']}" if solver == "iterative" else "–"
        wall_altfem, wall_peer = median(altfem, "wall_s"), median(peer, "wall_s")
        work_altfem, work_peer = assembly_and_solve(altfem), assembly_and_solve(peer)
        print(f"| {grid} | {element} | {altfem[0]['dofs']} | {solver_names[solver]} | {threads} "
              f"| {wall_altfem:.3f} | {wall_peer:.3f} | {wall_altfem / wall_peer:.2f} "
              f"| {work_altfem:.3f} | {work_peer:.3f} | {work_altfem / work_peer:.2f} | {iterations} "
              f"| {error(altfem):.1e} / {error(peer):.1e} |")
    print()


def sipg(runs: list[dict[str, str]]) -> None:
    runs = [run for run in runs if run["problem"] == "sipg"]
    if not runs:
        return
    print("Kaufmann et al. 2009 Table 1 (10³ cubes, SIPG, η = 20 E), 1 thread: assembly + solve, medians, s. "
          "altfem: complete P_k (bench_dg_table1); deal.II FE_DGP(k): the same space and discrete solution; "
          "FE_DGQ(k): tensor-product Q_k, more DOFs.\n")
    print("| k | solver altfem / deal.II | altfem DOFs | altfem | deal.II DGP | ratio | deal.II DGQ (DOFs) | ratio "
          "| CG iterations altfem / DGP / DGQ |")
    print("|---|---|---|---|---|---|---|---|---|")
    for degree in sorted({run["degree"] for run in runs}):
        of = lambda side, solver, space="": [run for run in runs if run["degree"] == degree and run["side"] == side
                                            and run["solver"] == solver and run.get("space", "") == space]
        # altfem's iterative solve: the faster of bench_dg_table1's two PCG cycles
        cycles = [cycle for cycle in ("two-level", "multilevel") if of("altfem", cycle)]
        best_cycle = min(cycles, key=lambda cycle: assembly_and_solve(of("altfem", cycle)))
        for altfem_solver, peer_solver, label in (("direct", "direct", "CHOLMOD / UMFPACK"),
                                                  (best_cycle, "amg", f"PCG {best_cycle} / CG+ML AMG")):
            altfem = of("altfem", altfem_solver)
            work = assembly_and_solve(altfem)
            cells, iterations = [], [altfem[0]["iterations"]]
            for space in ("dgp", "dgq"):
                peer = of("dealii", peer_solver, space)
                if peer:
                    peer_work = assembly_and_solve(peer)
                    dofs = f" ({peer[0]['dofs']})" if space == "dgq" else ""
                    cells += [f"{peer_work:.3f}{dofs}", f"{work / peer_work:.2f}"]
                    iterations.append(peer[0]["iterations"])
                else:
                    cells += ["not run", "–"]
                    iterations.append("–")
            iteration_text = " / ".join(iterations) if peer_solver == "amg" else "–"
            print(f"| {degree} | {label} | {altfem[0]['dofs']} | {work:.3f} | {' | '.join(cells)} | {iteration_text} |")
    print()


def main() -> None:
    runs = read(sys.argv[1])
    cantilever(runs)
    sipg(runs)


if __name__ == "__main__":
    main()
