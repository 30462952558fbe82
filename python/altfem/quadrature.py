"""altfem.quadrature: the cut-cell quadrature of the Finite Cell Method (Longva et al. 2020)."""
import json
import os
import tempfile

from ._command import run_command
from ._scene import as_scene


def monomials(cell="hex20", order=4, simplifier="caratheodory"):
    """Longva et al. 2020, §4.6 (Fig. 4's table): for each strength 1..order, the number of
    points and the largest monomial error of the initial and the simplified rules on one
    cut `cell` ("hex8", "hex20", "hex27", "tet4", "tet10"). `simplifier`: "caratheodory",
    "nnls" or "lp". Returns the rows of `altfem quadrature monomials --json`, a list of dicts."""
    return json.loads(run_command(["quadrature", "monomials", "--cell", cell, "--order", order, "--simplifier",
                                   simplifier, "--json"]))


def cut_cell(scene, cell, cell_type="hex20", resolution=4, order=4, simplifier="caratheodory"):
    """The quadrature rules of one background cell of `scene` (a Scene, or a scene file's
    path) on the grid of `resolution` cells (n, or (nx, ny, nz)) over its bounding box:
    the intersection rule of the embedded tetrahedra ("initial", Longva et al. 2020 §4.5)
    and its simplification to at most C(order+3, 3) points ("simplified", §4.6), as
    `altfem quadrature cell` writes them.

    cell: the grid cube (i, j, k). Returns a dict: the command's report (cut_cells,
    clipped_volume in m³, basis_size, max_residual, ...) and, for "initial" and
    "simplified", {"points": (n, 3) physical positions in m, "weights": (n,) reference
    weights, "physical_weights": (n,) weights times |det J|, m³}.
    """
    import meshio  # Debian's python3-meshio; only this function needs it

    def triple(value):
        return ",".join(str(part) for part in (value if isinstance(value, (list, tuple)) else [value] * 3))

    with tempfile.TemporaryDirectory(prefix="altfem-quadrature-") as folder:
        report = json.loads(run_command([
            "quadrature", "cell", "--scene", as_scene(scene)._file_for_commands(folder), "--cell", triple(cell),
            "--cell-type", cell_type, "--resolution", triple(resolution), "--order", order, "--simplifier",
            simplifier, "--out", folder, "--json"]))
        for rule in ("initial", "simplified"):
            points = meshio.read(os.path.join(folder, f"{rule}_rule.vtu"))
            report[rule] = {"points": points.points, "weights": points.point_data["weight"].ravel(),
                            "physical_weights": points.point_data["physical_weight"].ravel()}
    del report["files"]
    return report
