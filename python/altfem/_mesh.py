"""altfem.mesh: a method's mesh as `altfem mesh` builds it, without solving, as arrays."""
import json

from . import _core
from ._scene import as_scene


class Mesh:
    """A method's mesh at rest. Arrays are numpy views (no copy) that keep the mesh alive.

    points            (#points, 3) m
    cell_types        (#cells,) VTK cell types (10 Tet4, 24 Tet10, 12 Hex8, 25 Hex20, 42 polyhedron)
    connectivity      point ids of every cell, concatenated (a polyhedron: its distinct points)
    offsets           (#cells,) each cell's end in connectivity
    polyhedron_faces  per cell its faces, each a list of point ids (outward normal by the
                      right-hand rule); None for a mesh without polyhedra
    cell_data         dict of per-cell arrays: dg and harmonic "volume" (m³) and "kind"; fcm
                      "volume_fraction", "quadrature_points"
    facts             what `altfem mesh --json` prints (counts, sizes, slicing facts)
    warnings          what the user should know about this mesh, one line each
    """

    def __init__(self, output):
        arrays = output.arrays()
        self.points = arrays["points"]
        self.cell_types = arrays["cell_types"]
        self.connectivity = arrays["connectivity"]
        self.offsets = arrays["offsets"]
        self.polyhedron_faces = arrays.get("polyhedron_faces")
        self.cell_data = arrays["cell_data"]
        self.facts = json.loads(output.facts)
        self.warnings = list(output.warnings)

    def cell(self, index):
        """Point ids of cell `index`."""
        start = self.offsets[index - 1] if index > 0 else 0
        return self.connectivity[start:self.offsets[index]]

    def __repr__(self):
        return f"<altfem.Mesh {len(self.points)} points, {len(self.cell_types)} cells>"


def mesh(scene, method, source="", resolution=16, sliver_fraction=1e-3, octree_levels=0):
    """The mesh `method` builds for `scene` (a Scene, or a scene file's path), as `altfem mesh` does: for dg and
    harmonic, source "" (what the scene's block names), "convert" (the fem mesh, cell by
    cell) or "slice" (the geometry sliced by a grid of `resolution` cells along its longest
    side, pieces below `sliver_fraction` of a cell merged, inside cells joined up to
    2^octree_levels per side). Raises SceneError for bad input, ValueError for bad options."""
    if resolution < 1:
        raise ValueError(f"resolution: must be >= 1, got {resolution}")
    if not 0 <= sliver_fraction < 1:
        raise ValueError(f"sliver_fraction: must be in [0, 1), got {sliver_fraction}")
    if not 0 <= octree_levels <= 10:
        raise ValueError(f"octree_levels: must be in 0..10, got {octree_levels}")
    return Mesh(_core.mesh(*as_scene(scene)._source(), method, source, resolution, sliver_fraction, octree_levels))
