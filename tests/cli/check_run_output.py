"""Reads what `altfem run` wrote with meshio (independent of altfem's own code) and
checks it against summary.json: frame counts, cell counts, finite displacements.
Works for every method: Lagrange cells (then the points are the nodes, 3 DOFs each),
polyhedra, and per-element discontinuous fields (DG writes each element's own copy
of its vertices, so the DOF count is not 3 x points). Usage: check_run_output.py
OUTPUT_DIR. Exit code 0 when it matches."""
import json
import pathlib
import sys
import xml.etree.ElementTree as ElementTree

import meshio
import numpy

folder = pathlib.Path(sys.argv[1])
summary = json.loads((folder / "summary.json").read_text())
failures = []


def frames(pvd):
    return [folder / d.get("file") for d in ElementTree.parse(folder / pvd).getroot().iter("DataSet")]


volume_frames = frames("volume.pvd")
surface_frames = frames("surface.pvd")
if len(volume_frames) != summary["steps"] + 1 and len(volume_frames) < 2:
    failures.append(f"expected the initial and final volume frames, got {len(volume_frames)}")
last = meshio.read(volume_frames[-1])
cells = {block.type: len(block.data) for block in last.cells}
expected_total = sum(summary["elements"].values())
if sum(cells.values()) != expected_total:
    failures.append(f"volume cells {cells}, expected {expected_total} in all ({summary['elements']})")
lagrange_names = {"tet4": "tetra", "tet10": "tetra10", "hex8": "hexahedron", "hex20": "hexahedron20",
                  "hex27": "hexahedron27", "tet20": "VTK_LAGRANGE_TETRAHEDRON"}
for kind, count in summary["elements"].items():
    if kind in lagrange_names and cells.get(lagrange_names[kind], 0) != count:
        failures.append(f"volume cells {cells}, expected {count} {lagrange_names[kind]}")
displacement = last.point_data["displacement"]
if displacement.shape != (len(last.points), 3) or not numpy.isfinite(displacement).all():
    failures.append(f"displacement array {displacement.shape} not finite or of the wrong size")
nodal = all(kind in lagrange_names for kind in summary["elements"])
if nodal and len(last.points) != summary["dofs"] // 3:
    failures.append(f"{len(last.points)} points for {summary['dofs']} DOFs of a Lagrange mesh")
first = meshio.read(volume_frames[0])
if numpy.abs(first.point_data["displacement"]).max() != 0.0:
    failures.append("the initial frame is not at rest")
surface = meshio.read(folder / summary["surface"])
if surface.cells[0].type != "triangle" or not numpy.isfinite(surface.point_data["displacement"]).all():
    failures.append("the deformed surface is not a finite triangle surface")
if "surface_vertices" in summary["facts"] and len(surface.points) != summary["facts"]["surface_vertices"]:
    failures.append("the deformed surface is not the embedded triangle surface")
if summary["surface"] != surface_frames[-1].name:
    failures.append("summary.json's surface is not the last surface frame")
# Stress (issue #21): the elements' mean Cauchy stress and von Mises as cell data, the
# step's largest von Mises as the last column of log.txt, the same number.
if "von_mises" in last.cell_data:
    von_mises = numpy.concatenate(last.cell_data["von_mises"]).reshape(-1)
    stress = numpy.concatenate(last.cell_data["cauchy_stress"])
    if stress.shape != (len(von_mises), 9) or not numpy.isfinite(stress).all():
        failures.append(f"cauchy_stress array {stress.shape} not finite or of the wrong size")
    s = stress.reshape(-1, 3, 3)
    deviator = s - numpy.trace(s, axis1=1, axis2=2)[:, None, None] / 3 * numpy.eye(3)
    if not numpy.allclose(numpy.sqrt(1.5 * (deviator ** 2).sum(axis=(1, 2))), von_mises, rtol=1e-12, atol=0):
        failures.append("von_mises is not sqrt(3/2 s:s) of cauchy_stress")
    log = [line.split() for line in (folder / "log.txt").read_text().splitlines() if not line.startswith("#")]
    if log and summary["steps"] == len(log) and not numpy.isclose(float(log[-1][-1]), von_mises.max(), rtol=1e-5):
        failures.append(f"log.txt's last max_von_mises {log[-1][-1]} is not the last frame's {von_mises.max()}")
elif summary["method"] in ("fem", "fcm"):
    failures.append("no von_mises cell data in the volume output")
for failure in failures:
    print(failure)
sys.exit(1 if failures else 0)
