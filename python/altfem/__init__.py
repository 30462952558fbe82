"""altfem: elastic solids with the Finite Cell Method, interior-penalty DG, harmonic
polyhedral elements and conforming FEM, on identical scenes (docs/python.md).

    import altfem
    scene = altfem.Scene.load("scenes/cantilever.json")
    scene.set("discretization/fem/element", "hex20")     # as `altfem run --set`
    result = altfem.run(scene, method="fem")              # as `altfem run`
    result.summary["dofs"], result.frames[-1].surface_displacement   # dict, (n, 3) array

Bad input raises `SceneError` with the command line's one line; a numerical failure
raises `NumericalError`, whose `result` holds what the run reached. `compare` runs
`altfem compare` and returns its results table; `mesh` gives a method's mesh as arrays; `quadrature` holds the cut-cell
quadrature's tables (Longva et al. 2020), `harmonic` the harmonic basis of one polyhedron
(Martin et al. 2008), `dg` the element matrices of one DG element (Kaufmann et al. 2009).
"""
import os as _os

# libgomp reads its wait policy once, when the extension loads it: passive waiting keeps
# idle OpenMP workers off the cores CHOLMOD's BLAS threads need, as the `altfem`
# executable does (docs/conventions.md, "Threads").
_os.environ.setdefault("OMP_WAIT_POLICY", "passive")

from . import _core  # noqa: E402
from ._scene import Scene, SceneError  # noqa: E402
from ._run import Frame, NumericalError, Result, run  # noqa: E402
from ._compare import compare  # noqa: E402
from ._mesh import Mesh, mesh  # noqa: E402
from . import dg, harmonic, quadrature  # noqa: E402


def methods():
    """The methods of this build, e.g. ['fem', 'fcm', 'dg', 'harmonic']."""
    return list(_core.methods())


__all__ = ["Scene", "SceneError", "NumericalError", "Frame", "Result", "run", "compare", "Mesh", "mesh", "methods",
           "quadrature", "harmonic", "dg"]
