#!/usr/bin/python3
"""CG + GAMG under refinement against issue #37's goal: at most 30 iterations a solve to a
relative residual of 1e-8 on the cantilever and the cut cylinder, growing at most 20% per
8x refinement, up to about 2M DOFs. Every row is one `altfem run` with the PETSc defaults
(the rigid-body modes as GAMG's near-null space, the coarser space inside as its coarse
level, the method's smoother on the finest level), read back from its summary.json; a
solve is one Newton iteration's (the cylinder's hyperelastic step and the half-ball's
tolerance take several: their mean is shown). Growth is against the row above, per 8x
refinement (each grid step halves the cells' size: 8x the cells; a step of another ratio
is scaled to 8x by its logarithm). Peak memory is the
run's resident set (`/usr/bin/time -f %M`). Prints a markdown table; `--largest` adds the
grids of 0.5-2M DOFs (tens of minutes, up to 12 GB).

    /usr/bin/python3 bench/petsc_refinement.py [--altfem build/bin/altfem] [--out out/petsc_refinement]
        [--largest] [--problem TEXT]
"""
import json
import math

import petsc_runs

ROOT = petsc_runs.ROOT
CANTILEVER = ROOT / "scenes/cantilever.json"
CYLINDER = ROOT / "scenes/twisting_cylinder.json"


def cantilever_grids(count):
    return [[20 * 2**level, 2 * 2**level, 2 * 2**level] for level in range(count)]


def problems(largest):
    """(label, method, scene, [settings per grid, coarse to fine]) per problem."""
    def grid_settings(key, grids, *more):
        return [[f"{key}={json.dumps(grid)}", *more] for grid in grids]

    fem = "discretization/fem/resolution"
    rows = [
        ("fem hex8 cantilever", "fem", CANTILEVER,
         grid_settings(fem, cantilever_grids(5 if largest else 4), "discretization/fem/element=hex8")),
        ("fem hex20 cantilever", "fem", CANTILEVER,
         grid_settings(fem, cantilever_grids(4 if largest else 3), "discretization/fem/element=hex20")),
        ("fem tet10 cantilever", "fem", CANTILEVER,
         grid_settings(fem, cantilever_grids(4 if largest else 3) + ([[200, 20, 20]] if largest else []),
                       "discretization/fem/element=tet10")),
        ("harmonic cantilever", "harmonic", CANTILEVER,
         grid_settings("discretization/harmonic/convert/resolution", cantilever_grids(4))),
    ]
    for degree in [1, 2]:
        rows.append((f"dg k={degree} cantilever", "dg", CANTILEVER,
                     grid_settings("discretization/dg/resolution", cantilever_grids(4 if largest else 3),
                                   f"discretization/dg/degree={degree}")))
    # The cut cylinder: its first time step (hyperelastic, a few Newton solves), with fcm's
    # default stabilisation and with the face ghost penalty in its place.
    cylinder = [[4, 4, 16], [8, 8, 32], [16, 16, 64]]
    common = ["time/steps=1", "output/surface=false"]
    rows.append(("fcm hex20 cut cylinder", "fcm", CYLINDER,
                 grid_settings("discretization/fcm/resolution", cylinder, *common)))
    rows.append(("fcm hex20 cut cylinder, ghost penalty", "fcm", CYLINDER,
                 grid_settings("discretization/fcm/resolution", cylinder, *common,
                               "discretization/fcm/ghost_penalty=0.001", "discretization/fcm/stabilization=0")))
    return rows


def main():
    arguments = petsc_runs.arguments(__doc__, "petsc_refinement")

    print("| problem | grid | DOFs | iterations a solve | growth per 8× | set-up s | solve s | peak GB |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    for index, (label, method, scene, grids) in enumerate(problems(arguments.largest)):
        if arguments.problem not in label:
            continue
        previous = None
        for level, settings in enumerate(grids):
            grid = settings[0].split("=", 1)[1]
            summary, error = petsc_runs.run(arguments.altfem, scene, method, ["solver/linear=petsc", *settings],
                                            arguments.out / f"{index}-{level}")
            if summary is None:
                print(f"| {label} | {grid} | | failed: {error} | | | | |", flush=True)
                break
            per_solve = summary["linear_iterations"] / summary["newton_iterations"]
            growth = ""
            if previous is not None:
                ratio = math.prod(json.loads(grid)) / math.prod(json.loads(previous[0]))
                growth = f"{(per_solve / previous[1]) ** (math.log(8) / math.log(ratio)) - 1:+.0%}"
            previous = (grid, per_solve)
            timings = summary["timings_s"]
            solves = f" ({summary['newton_iterations']} solves)" if summary["newton_iterations"] > 1 else ""
            print(f"| {label} | {grid} | {summary['dofs']:,} | {per_solve:.1f}{solves} | {growth} | "
                  f"{timings['analysis'] + timings['factorisation']:.2f} | {timings['solve']:.2f} | "
                  f"{summary['peak_gb']:.2f} |", flush=True)


if __name__ == "__main__":
    main()
