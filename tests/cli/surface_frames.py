"""The last surface frame of a run (its summary.json names it) and the points of it whose
rest positions lie in a box: what the check_*.py scripts of tests/cli read back."""
import json
import pathlib

import meshio
import numpy


def last_surface(folder):
    """The run's last surface frame (meshio.Mesh); its points are deformed positions."""
    summary = json.loads((pathlib.Path(folder) / "summary.json").read_text())
    return meshio.read(pathlib.Path(folder) / summary["surface"])


def rest_positions(surface):
    """#points × 3: the frame's points without their displacement."""
    return surface.points - surface.point_data["displacement"]


def in_box(surface, box_min, box_max):
    """Boolean mask of the points whose rest positions lie in [box_min, box_max]."""
    rest = rest_positions(surface)
    return numpy.all((rest >= numpy.asarray(box_min)) & (rest <= numpy.asarray(box_max)), axis=1)
