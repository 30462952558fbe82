#!/usr/bin/python3
"""Peak memory of dg per degree of freedom (issue #35): `altfem run` of a unit cube of k = 1
polyhedra on n³ grids with PCG and block Jacobi (bench/scenes/dg_cube.json, static,
gravity), its peak resident set read back from the kernel (getrusage of the child).

Goal: at most 3 KB per DOF at the largest size (393,216 DOFs for n = 32), where K itself
(84 entries per row, 12 bytes each) is 1 KB per DOF and what does not grow with the DOFs
(the executable, its libraries) is spread thin. Prints a table and PASS/FAIL.

Usage: bench/dg_memory.py [--altfem build/bin/altfem] [--sizes 16,24,32] [--linear pcg]
"""
import argparse
import json
import os
import pathlib
import subprocess
import tempfile

GOAL_BYTES_PER_DOF = 3 * 1024


def peak_of_run(altfem, scene, size, linear):
    """(DOFs, peak resident bytes) of one run in its own process."""
    with tempfile.TemporaryDirectory() as out:
        command = [altfem, "run", scene, "--method", "dg", "--out", out,
                   "--set", f"discretization/dg/resolution=[{size},{size},{size}]", "--set", f"solver/linear={linear}"]
        # A fresh Python child per run: RUSAGE_CHILDREN keeps the largest child's peak so far.
        probe = ("import resource, subprocess, sys; subprocess.run(sys.argv[1:], check=True, "
                 "stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL); "
                 "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")
        environment = {**os.environ, "OMP_WAIT_POLICY": "passive"}
        peak_kilobytes = int(subprocess.run(["/usr/bin/python3", "-c", probe, *command], check=True,
                                            capture_output=True, text=True, env=environment).stdout)
        summary = json.loads((pathlib.Path(out) / "summary.json").read_text())
    return summary["dofs"], peak_kilobytes * 1024


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--altfem", default="build/bin/altfem")
    parser.add_argument("--scene", default=str(pathlib.Path(__file__).parent / "scenes" / "dg_cube.json"))
    parser.add_argument("--sizes", default="16,24,32")
    parser.add_argument("--linear", default="pcg")
    arguments = parser.parse_args()
    print(f"{'grid':>6} {'DOFs':>9} {'peak MB':>9} {'KB/DOF':>7}")
    per_dof = 0.0
    for size in (int(value) for value in arguments.sizes.split(",")):
        dofs, peak = peak_of_run(arguments.altfem, arguments.scene, size, arguments.linear)
        per_dof = peak / dofs
        print(f"{size:>4}^3 {dofs:>9} {peak / 2**20:>9.0f} {per_dof / 1024:>7.2f}")
    verdict = "PASS" if per_dof <= GOAL_BYTES_PER_DOF else "FAIL"
    print(f"{verdict}: {per_dof / 1024:.2f} KB per DOF at the largest size (goal <= {GOAL_BYTES_PER_DOF // 1024} KB)")


if __name__ == "__main__":
    main()
