"""Checks that a run of a scene scaled by S is the unit run scaled: the last surface
frames have the same rest points up to the factor S, and displacements u_S / S^POWER equal
the unit run's to 1e-6 of its largest. Usage: check_scaled_run.py UNIT_DIR SCALED_DIR S
POWER. Exit 0 when they do."""
import sys

import numpy

from surface_frames import last_surface, rest_positions

unit, scaled = last_surface(sys.argv[1]), last_surface(sys.argv[2])
factor, power = float(sys.argv[3]), float(sys.argv[4])
rest_unit, rest_scaled = rest_positions(unit), rest_positions(scaled) / factor
if rest_unit.shape != rest_scaled.shape or numpy.abs(rest_unit - rest_scaled).max() > 1e-9:
    sys.exit("the scaled run's surface is not the unit run's scaled")
unit_u = unit.point_data["displacement"]
scaled_u = scaled.point_data["displacement"] / factor**power
largest = numpy.abs(unit_u).max()
difference = numpy.abs(scaled_u - unit_u).max()
print(f"largest displacement {largest:.6e} (unit run), largest difference of the scaled run's / S^{power:g}: "
      f"{difference:.3e} ({difference / largest:.2e} relative)")
sys.exit(0 if largest > 0 and difference <= 1e-6 * largest else 1)
