"""Reads what `altfem run` wrote with meshio (independent of altfem's own code) and
checks it against summary.json: frame counts, cell types and counts, finite
displacements. Usage: check_run_output.py OUTPUT_DIR. Exit code 0 when it matches."""
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
(kind, expected_cells), = summary["elements"].items()
meshio_names = {"tet4": "tetra", "tet10": "tetra10", "hex8": "hexahedron", "hex20": "hexahedron20",
                "hex27": "hexahedron27", "tet20": "VTK_LAGRANGE_TETRAHEDRON"}
cells = {block.type: len(block.data) for block in last.cells}
if cells.get(meshio_names[kind], 0) != expected_cells:
    failures.append(f"volume cells {cells}, expected {expected_cells} {meshio_names[kind]}")
displacement = last.point_data["displacement"]
if displacement.shape != (summary["dofs"] // 3, 3) or not numpy.isfinite(displacement).all():
    failures.append(f"displacement array {displacement.shape} not finite or of the wrong size")
first = meshio.read(volume_frames[0])
if numpy.abs(first.point_data["displacement"]).max() != 0.0:
    failures.append("the initial frame is not at rest")
surface = meshio.read(folder / summary["surface"])
if surface.cells[0].type != "triangle" or len(surface.points) != summary["facts"]["surface_vertices"]:
    failures.append("the deformed surface is not the embedded triangle surface")
if summary["surface"] != surface_frames[-1].name:
    failures.append("summary.json's surface is not the last surface frame")
for failure in failures:
    print(failure)
sys.exit(1 if failures else 0)
