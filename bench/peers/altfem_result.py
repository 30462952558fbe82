#!/usr/bin/env python3
"""altfem's results as lines of key=value pairs like the deal.II peers print (issue #39).

    altfem_result.py run OUT_DIR X Y Z
    -> dofs=... setup_s=... assembly_s=... solve_s=... iterations=... tip_z=...
    bench_dg_table1 --row "IP k=1" ... | altfem_result.py dg-table1
    -> one line per solver: solver=direct|two-level|multilevel dofs=... assembly_s=... solve_s=... iterations=...

run: one `altfem run` output folder.
From OUT_DIR/summary.json's timings_s: assembly = quadrature (shape data at the rule's
points, which deal.II's FEValues computes inside its assembly) + assembly; solve = analysis +
factorisation (CHOLMOD's, or the preconditioner's set-up) + solve. tip_z: the z displacement
of the mesh node nearest to X Y Z in the last volume_*.vtu (raw appended data with UInt64
block headers, as altfem writes it). Standard library only, so the script needs no numpy.
"""
import glob
import json
import re
import struct
import sys


def appended_array(text: bytes, data: bytes, name: str) -> list[float]:
    header = re.search(rb'<DataArray type="Float64" Name="' + name.encode() + rb'"[^>]*offset="(\d+)"', text)
    if header is None:
        raise SystemExit(f"no Float64 array {name} in the VTU")
    offset = int(header.group(1))
    (length,) = struct.unpack_from("<Q", data, offset)
    return list(struct.unpack_from(f"<{length // 8}d", data, offset + 8))


def tip_z(out_dir: str, target: list[float]) -> float:
    path = sorted(glob.glob(f"{out_dir}/volume_*.vtu"))[-1]
    raw = open(path, "rb").read()
    start = raw.index(b"<AppendedData")
    data = raw[raw.index(b"_", start) + 1 :]  # the appended block starts after the underscore
    points = appended_array(raw[:start], data, "Points")
    displacement = appended_array(raw[:start], data, "displacement")
    nearest = min(range(len(points) // 3),
                  key=lambda p: sum((points[3 * p + a] - target[a]) ** 2 for a in range(3)))
    if sum((points[3 * nearest + a] - target[a]) ** 2 for a in range(3)) > 1e-20:
        raise SystemExit(f"no node at {target} in {path}")
    return displacement[3 * nearest + 2]


def run(out_dir: str, target: list[float]) -> None:
    summary = json.load(open(f"{out_dir}/summary.json"))
    timings = summary["timings_s"]
    assembly = timings["quadrature"] + timings["assembly"]
    solve = timings["analysis"] + timings["factorisation"] + timings["solve"]
    print(f"dofs={summary['dofs']} setup_s={timings['setup']:.6f} assembly_s={assembly:.6f} solve_s={solve:.6f} "
          f"iterations={summary['linear_iterations']} tip_z={tip_z(out_dir, target):.10e}")


def dg_table1(lines: list[str]) -> None:
    """The rows of bench_dg_table1 (ms; its PCG solve includes the preconditioner's set-up)."""
    for line in lines:
        if "|" not in line or not line.startswith(("IP", "BZ")):
            continue
        left, right = line.split("|")
        _, _, dofs, assembly, direct, *_ = left.split()
        cycle, iterations, _, _, _, solve, *_ = right.split()
        if cycle == "two-level":  # the first of a row's two lines: print the direct solve once
            print(f"solver=direct dofs={dofs} assembly_s={float(assembly) / 1e3:.6f} "
                  f"solve_s={float(direct) / 1e3:.6f} iterations=0")
        print(f"solver={cycle} dofs={dofs} assembly_s={float(assembly) / 1e3:.6f} "
              f"solve_s={float(solve) / 1e3:.6f} iterations={iterations}")


def main() -> None:
    if sys.argv[1] == "run":
        run(sys.argv[2], [float(value) for value in sys.argv[3:6]])
    elif sys.argv[1] == "dg-table1":
        dg_table1(sys.stdin.read().splitlines())
    else:
        raise SystemExit("usage: altfem_result.py run OUT_DIR X Y Z | altfem_result.py dg-table1")


if __name__ == "__main__":
    main()
