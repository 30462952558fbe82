"""Checks that the mean of one displacement component over the points of a run's last
surface frame whose rest positions lie inside a box is in [LOW, HIGH]. Usage:
check_mean_displacement.py OUTPUT_DIR XMIN YMIN ZMIN XMAX YMAX ZMAX COMPONENT LOW HIGH (the
box closed, widened by 1e-9 m; COMPONENT 0, 1 or 2). Exit 0 when the mean lies in the
interval."""
import sys

from surface_frames import in_box, last_surface

surface = last_surface(sys.argv[1])
inside = in_box(surface, [float(v) - 1e-9 for v in sys.argv[2:5]], [float(v) + 1e-9 for v in sys.argv[5:8]])
component, low, high = int(sys.argv[8]), float(sys.argv[9]), float(sys.argv[10])
if not inside.any():
    sys.exit("no surface point in the box")
values = surface.point_data["displacement"][inside, component]
mean = values.mean()
print(f"{inside.sum()} points: mean displacement[{component}] {mean:.6g} (range {values.min():.6g} .. "
      f"{values.max():.6g}), expected in [{low:.6g}, {high:.6g}]")
sys.exit(0 if low <= mean <= high else 1)
