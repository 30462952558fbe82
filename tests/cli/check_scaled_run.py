"""Checks that a run of a scene scaled by S is the unit run scaled: the last surface
frames have the same points up to the factor S, and displacements u_S / S^POWER equal
the unit run's to 1e-6 of its largest. Usage: check_scaled_run.py UNIT_DIR SCALED_DIR S
POWER. Exit 0 when they do."""
import json
import pathlib
import sys

import meshio
import numpy


def last_surface(folder):
    summary = json.loads((pathlib.Path(folder) / "summary.json").read_text())
    return meshio.read(pathlib.Path(folder) / summary["surface"])


unit, scaled = last_surface(sys.argv[1]), last_surface(sys.argv[2])
factor, power = float(sys.argv[3]), float(sys.argv[4])
unit_u = unit.point_data["displacement"]
scaled_u = scaled.point_data["displacement"] / factor**power
rest_unit = unit.points - unit_u
rest_scaled = (scaled.points - scaled.point_data["displacement"]) / factor
if rest_unit.shape != rest_scaled.shape or numpy.abs(rest_unit - rest_scaled).max() > 1e-9:
    sys.exit("the scaled run's surface is not the unit run's scaled")
largest = numpy.abs(unit_u).max()
difference = numpy.abs(scaled_u - unit_u).max()
print(f"largest displacement {largest:.6e} (unit run), largest difference of the scaled run's / S^{power:g}: "
      f"{difference:.3e} ({difference / largest:.2e} relative)")
sys.exit(0 if largest > 0 and difference <= 1e-6 * largest else 1)
