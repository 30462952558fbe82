#!/usr/bin/python3
"""PETSc's preconditioners against altfem's own and CHOLMOD (issue #37, step 1): CG
iterations to a relative residual of 1e-8 and seconds per method and size, for GAMG with
the rigid-body modes as its near-null space (solver.rigid_body_modes, the default), on
higher-order fem and fcm elements and on dg working on a first-order space inside
(solver.p_multigrid, the default) and with the method's preconditioner smoothing its
finest level (solver.method_smoother, the default), GAMG on the whole space, GAMG with its
own smoother, GAMG without the rotations, hypre's BoomerAMG with nodal
coarsening, altfem's own PCG (the method's preconditioner, or incomplete Cholesky for fem),
and CHOLMOD. Each row is one `altfem run`
of a static scene, read back from its summary.json: set-up is the factorisation phase
(the preconditioner's set-up for the iterative solvers), solve the solve phase. Prints a
markdown table; `--largest` adds the biggest grids (minutes).

    /usr/bin/python3 bench/petsc_study.py [--altfem build/bin/altfem] [--out out/petsc_study] [--largest]
        [--solver SOLVER] [--problem TEXT]
"""
import json

import petsc_runs

ROOT = petsc_runs.ROOT
CANTILEVER = ROOT / "scenes/cantilever.json"
HALF_BALL = ROOT / "scenes/manufactured_half_ball.json"

SOLVERS = {
    "CHOLMOD": ["solver/linear=cholmod"],
    "GAMG + rigid modes": ["solver/linear=petsc"],
    # GAMG's own smoother on every level, where the row above smooths the finest level
    # with the method's preconditioner (fcm's Additive Schwarz, dg's; solver.method_smoother).
    # GAMG on the whole higher-order space, where the row above works on the first-order
    # space inside as a two-level p-multigrid's coarse level (solver.p_multigrid: fem and
    # fcm on quadratic elements, dg's vertex space; harmonic and Hex8 have none, so their rows agree).
    "GAMG on the whole space": ["solver/linear=petsc", "solver/p_multigrid=false"],
    "GAMG, its own smoother": ["solver/linear=petsc", "solver/method_smoother=false"],
    "GAMG, translations only": ["solver/linear=petsc", "solver/rigid_body_modes=false"],
    # GAMG without its aggressive coarsening (MIS-2 on the squared graph) on the finest
    # level, the default's or, with the first-order coarse level, that level's GAMG's.
    "GAMG, no aggressive coarsening": ["solver/linear=petsc",
                                       "solver/petsc_options=-ksp_type cg -pc_type gamg "
                                       "-pc_gamg_aggressive_coarsening 0 -mg_coarse_pc_gamg_aggressive_coarsening 0"],
    "BoomerAMG (nodal)": ["solver/linear=petsc",
                          "solver/petsc_options=-ksp_type cg -pc_type hypre -pc_hypre_type boomeramg "
                          "-pc_hypre_boomeramg_nodal_coarsen 6"],
    "altfem PCG": ["solver/linear=pcg"],
}
# altfem's own preconditioner per method: fem has none of its own (incomplete Cholesky is
# its best general one); fcm, dg and harmonic bring theirs (Additive Schwarz, block Jacobi).
OWN_PRECONDITIONER = {"fem": ["solver/preconditioner=incomplete_cholesky"]}


def problems(largest):
    """(label, method, scene, settings) per problem, coarse to fine."""
    grids = [[20, 2, 2], [40, 4, 4], [80, 8, 8]] + ([[160, 16, 16]] if largest else [])
    rows = []
    for element in ["hex8", "hex20", "tet10"]:
        for grid in grids[:3] if element == "hex8" else grids[:2 + largest]:
            rows.append((f"fem {element} {grid}", "fem", CANTILEVER,
                         [f"discretization/fem/element={element}", f"discretization/fem/resolution={json.dumps(grid)}"]))
    for resolution in [[8, 8, 4], [16, 16, 8]] + ([[32, 32, 16]] if largest else []):
        rows.append((f"fcm hex20 half-ball {resolution}", "fcm", HALF_BALL,
                     [f"discretization/fcm/resolution={json.dumps(resolution)}"]))
    # fcm's other remedy for small cuts: the face ghost penalty in place of the
    # stabilisation, which leaves no function of tiny energy for the smoother to miss.
    for resolution in [[8, 8, 4], [16, 16, 8]] + ([[32, 32, 16]] if largest else []):
        rows.append((f"fcm hex20 half-ball, ghost penalty {resolution}", "fcm", HALF_BALL,
                     [f"discretization/fcm/resolution={json.dumps(resolution)}",
                      "discretization/fcm/ghost_penalty=0.001", "discretization/fcm/stabilization=0"]))
    for degree in [1, 2]:
        for grid in [[20, 2, 2], [40, 4, 4]]:
            rows.append((f"dg k={degree} {grid}", "dg", CANTILEVER,
                         [f"discretization/dg/degree={degree}", f"discretization/dg/resolution={json.dumps(grid)}"]))
    for grid in [[20, 2, 2], [40, 4, 4]] + ([[80, 8, 8]] if largest else []):
        rows.append((f"harmonic {grid}", "harmonic", CANTILEVER,
                     [f"discretization/harmonic/convert/resolution={json.dumps(grid)}"]))
    return rows


def main():
    arguments = petsc_runs.arguments(
        __doc__, "petsc_study", (["--solver"], {"choices": list(SOLVERS), "help": "only this row of each problem"}))

    print("| problem | DOFs | solver | CG iterations | set-up s | solve s |")
    print("|---|---:|---|---:|---:|---:|")
    for index, (label, method, scene, settings) in enumerate(problems(arguments.largest)):
        if arguments.problem not in label:
            continue
        for solver_index, (solver, solver_settings) in enumerate(SOLVERS.items()):
            if arguments.solver and solver != arguments.solver:
                continue
            extra = OWN_PRECONDITIONER.get(method, []) if solver == "altfem PCG" else []
            out = arguments.out / f"{index}-{solver_index}"
            summary, error = petsc_runs.run(arguments.altfem, scene, method, settings + solver_settings + extra, out)
            if summary is None:
                print(f"| {label} | | {solver} | failed: {error} | | |", flush=True)
                continue
            timings = summary["timings_s"]
            iterations = summary["linear_iterations"] if solver != "CHOLMOD" else "direct"
            # The half-ball's Newton tolerance (1e-10) takes a second solve after a first
            # to 1e-8: its CG iterations are the two solves' sum.
            if solver != "CHOLMOD" and summary["newton_iterations"] > 1:
                iterations = f"{iterations} ({summary['newton_iterations']} solves)"
            print(f"| {label} | {summary['dofs']:,} | {solver} | {iterations} | "
                  f"{timings['analysis'] + timings['factorisation']:.3f} | {timings['solve']:.3f} |", flush=True)


if __name__ == "__main__":
    main()
