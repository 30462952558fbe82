"""altfem.run: the run of `altfem run`, in this process, its frames kept as numpy arrays."""
import json
import shutil
import tempfile

from . import _core
from ._scene import as_scene

NumericalError = _core.NumericalError
NumericalError.__doc__ = ("A numerical failure (Newton not converging, a singular matrix, an inverted element); "
                          "the message names the step and iteration, and `result` holds what the run reached.")


class Frame:
    """One output time of a run. Arrays are numpy views of the run's own memory (no copy)
    and stay valid as long as any of them or the Result is alive.

    time                  the state's time in s (a static run: the load factor, 0..1)
    points                (#points, 3) the method's volume mesh at rest, m
    displacement          (#points, 3) its displacement, m
    cell_types            (#cells,) VTK cell types (24 Tet10, 25 Hex20, 42 polyhedron, ...)
    connectivity, offsets VTK's cell arrays: cell c is connectivity[offsets[c-1]:offsets[c]]
    stress                (#cells, 3, 3) each element's mean Cauchy stress, Pa (None where
                          the method's elements are not the volume cells)
    von_mises             (#cells,) its von Mises stress, Pa (None likewise)
    surface_vertices      (#vertices, 3) the embedded surface at rest, m: the same points in
                          every method, where altfem compares them
    surface_triangles     (#triangles, 3) vertex ids
    surface_displacement  (#vertices, 3) their displacement, m
    """

    def __init__(self, arrays):
        self.time = arrays["time"]
        self.points = arrays["points"]
        self.displacement = arrays["point_data"].get("displacement")
        self.cell_types = arrays["cell_types"]
        self.connectivity = arrays["connectivity"]
        self.offsets = arrays["offsets"]
        self.stress = arrays["cell_data"].get("cauchy_stress")
        self.von_mises = arrays["cell_data"].get("von_mises")
        self.surface_vertices = arrays["surface_vertices"]
        self.surface_triangles = arrays["surface_triangles"]
        self.surface_displacement = arrays["surface_displacement"]

    def __repr__(self):
        return (f"<altfem.Frame time={self.time:g}: {len(self.points)} points, {len(self.cell_types)} cells, "
                f"{len(self.surface_vertices)} surface vertices>")


class Result:
    """What `run` returns: `summary` (summary.json as a dict), `frames` (a list of Frame,
    one per output time: the initial state, then every output.every steps), `warnings`
    (the run's warnings, one line each) and `out` (the output folder, None when the run
    wrote into a temporary one)."""

    def __init__(self, output, out):
        self._output = output
        self.summary = json.loads(output.summary)
        self.warnings = list(output.warnings) + list(self.summary.get("warnings", []))
        self.frames = [Frame(output.frame_arrays(index)) for index in range(output.frame_count())]
        self.out = out

    def __repr__(self):
        summary = self.summary
        return (f"<altfem.Result {summary.get('scene')} with {summary.get('method')}: {summary.get('dofs')} DOFs, "
                f"{summary.get('steps')} steps, status {summary.get('status')!r}>")


def run(scene, method, out=None):
    """Runs `scene` (a Scene, or a scene file's path) with `method` ("fem", "fcm", "dg" or
    "harmonic"), as `altfem run SCENE --method METHOD --out OUT` does; returns a Result.

    out: the folder for summary.json, log.txt and the VTU frames, checked as the command
    line checks it; None writes them into a temporary folder removed afterwards.
    Progress is shown on a terminal only (not in a notebook or under pytest).
    Raises SceneError for bad input (nothing written) and NumericalError for a numerical
    failure, whose `result` holds the summary and frames up to the last converged state.
    """
    folder = tempfile.mkdtemp(prefix="altfem-run-") if out is None else str(out)
    try:
        output = _core.run(*as_scene(scene)._source(), method, folder if out is not None else folder + "/run")
    finally:
        if out is None:
            shutil.rmtree(folder, ignore_errors=True)
    result = Result(output, out)
    if output.error:
        error = NumericalError(output.error)
        error.result = result
        raise error
    return result
