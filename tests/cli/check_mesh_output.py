"""Reads what `altfem mesh` wrote with meshio (independent of altfem's own code) and
compares it with the facts it printed as JSON: cell count, polyhedron cells for dg and
harmonic, cell data "volume" summing to the printed volume and to the volume of the
written polyhedra by the divergence theorem (fans of every face, outward per cell),
"kind" present with known values.

  check_mesh_output.py MESH.vtu FACTS.json        exit 0 = match, 1 = mismatch
"""
import json
import sys

import meshio
import numpy as np

try:
    mesh = meshio.read(sys.argv[1])
    points, cells, cell_data = mesh.points, mesh.cells, mesh.cell_data
except ValueError:
    # meshio 5.0 sorts polyhedra into blocks by node count but their cell data by another
    # key, and Mesh() rejects the mismatch; the reader's arrays are complete (totals hold).
    reader = meshio.vtu._vtu.VtuReader(sys.argv[1])
    points, cells, cell_data = reader.points, reader.cells, reader.cell_data
with open(sys.argv[2]) as file:
    facts = json.load(file)
cell_count = sum(len(block.data) for block in cells)
problems = []
if cell_count != facts["cells"]["total"]:
    problems.append(f"{cell_count} cells, facts say {facts['cells']['total']}")
if facts["method"] in ("dg", "harmonic"):
    types = {block.type for block in cells}
    if not all(kind.startswith("polyhedron") for kind in types):
        problems.append(f"cell types {types}, expected polyhedra only")
    volume = sum(np.sum(block) for block in cell_data["volume"])
    if abs(volume - facts["volume"]) > 1e-12 * abs(facts["volume"]):
        problems.append(f"cell data volume sums to {volume}, facts say {facts['volume']}")
    enclosed = 0.0
    for block in cells:
        for polyhedron in block.data:
            for face in polyhedron:
                corners = points[np.asarray(face)]
                for i in range(1, len(corners) - 1):
                    enclosed += np.linalg.det(np.array([corners[0], corners[i], corners[i + 1]])) / 6
    if abs(enclosed - facts["volume"]) > 1e-10 * abs(facts["volume"]):
        problems.append(f"the written polyhedra enclose {enclosed}, facts say {facts['volume']}")
    if "kind" not in cell_data:
        problems.append("no cell data 'kind'")
    else:
        kinds = set(np.concatenate([np.ravel(block) for block in cell_data["kind"]]).astype(int))
        if not kinds <= {0, 1, 2, 3, 4}:
            problems.append(f"cell data 'kind' has values {kinds}, expected 0..4")
for problem in problems:
    print("check_mesh_output:", problem)
sys.exit(1 if problems else 0)
