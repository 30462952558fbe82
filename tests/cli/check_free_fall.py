"""Checks that the points of a run's last surface frame whose rest positions lie inside a
box fell freely: their displacement is the backward-Euler free fall
u_n = g dt^2 n (n + 1) / 2 of every step n (exact for a linear material body that nothing
holds). Usage: check_free_fall.py OUTPUT_DIR XMIN YMIN ZMIN XMAX YMAX ZMAX GZ DT STEPS.
Exit 0 when every point's z displacement matches to 1e-6 relative."""
import sys

import numpy

from surface_frames import in_box, last_surface

surface = last_surface(sys.argv[1])
inside = in_box(surface, [float(v) for v in sys.argv[2:5]], [float(v) for v in sys.argv[5:8]])
gravity_z, dt, steps = float(sys.argv[8]), float(sys.argv[9]), int(sys.argv[10])
if not inside.any():
    sys.exit("no surface point in the box")
expected = gravity_z * dt * dt * steps * (steps + 1) / 2
fall = surface.point_data["displacement"][inside, 2]
error = numpy.abs(fall - expected).max() / abs(expected)
print(f"{inside.sum()} points: z displacement {fall.min():.6f} .. {fall.max():.6f}, free fall {expected:.6f}, "
      f"relative error {error:.2e}")
sys.exit(0 if error < 1e-6 else 1)
