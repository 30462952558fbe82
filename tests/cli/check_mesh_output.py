"""Reads what `altfem mesh` wrote with meshio (independent of altfem's own code) and
compares it with the facts it printed as JSON: cell count, polyhedron cells for dg and
harmonic, cell data "volume" summing to the printed volume, "kind" present.

  check_mesh_output.py MESH.vtu FACTS.json        exit 0 = match, 1 = mismatch
"""
import json
import sys

import meshio
import numpy as np

mesh = meshio.read(sys.argv[1])
with open(sys.argv[2]) as file:
    facts = json.load(file)
cell_count = sum(len(block.data) for block in mesh.cells)
problems = []
if cell_count != facts["cells"]["total"]:
    problems.append(f"{cell_count} cells, facts say {facts['cells']['total']}")
if facts["method"] in ("dg", "harmonic"):
    types = {block.type for block in mesh.cells}
    if not all(kind.startswith("polyhedron") for kind in types):
        problems.append(f"cell types {types}, expected polyhedra only")
    volume = sum(np.sum(block) for block in mesh.cell_data["volume"])
    if abs(volume - facts["volume"]) > 1e-12 * abs(facts["volume"]):
        problems.append(f"cell data volume sums to {volume}, facts say {facts['volume']}")
    if "kind" not in mesh.cell_data:
        problems.append("no cell data 'kind'")
for problem in problems:
    print("check_mesh_output:", problem)
sys.exit(1 if problems else 0)
