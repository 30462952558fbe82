#!/usr/bin/python3
"""Speed against accuracy on a curved body: which method gives the smallest error for the
time you have? (altfem compare, drawn as a Pareto plot.)

The half ball of radius 1 with a manufactured solution u*(x) (scenes/manufactured_half_ball.json):
the body force and the traction on the flat face are computed from u*, so the exact
displacement is known everywhere and each run's L2 error ‖u − u*‖ is exact, not measured
against another run. Each method runs at two resolutions; a run is on the Pareto front
when no other run is both faster and more accurate.

    /usr/bin/python3 examples/python/speed_accuracy.py [--quick] [--out DIR]
"""
import pathlib
import tempfile

from teaching import altfem, arguments, check, finish, plt, save, scene

options = arguments(__doc__.splitlines()[0])

sweeps = {
    "discretization/fem/max_cell_size": [0.4, 0.2],
    "discretization/fcm/resolution": [[4, 4, 2], [8, 8, 4]],
    "discretization/dg/max_cell_size": [0.5, 0.3],
    "discretization/harmonic/convert/max_cell_size": [0.4, 0.25],
}
methods = ["fem", "fcm"] if options.quick else ["fem", "fcm", "dg", "harmonic"]
folder = pathlib.Path(options.out) / "speed_accuracy" if not options.quick else pathlib.Path(tempfile.mkdtemp())
rows = altfem.compare(scene("manufactured_half_ball"), out=folder, methods=methods, reference="fem",
                      sweeps={key: values for key, values in sweeps.items() if key.split("/")[1] in methods})
# Every row is a run of its own; the reference only matters for the surface error, which
# the exact L2 error makes unnecessary here.
runs = rows

print(f"{'method':9} {'configuration':42} {'DOFs':>7} {'time (s)':>9} {'L2 error':>10}")
for row in sorted(runs, key=lambda row: row["total_s"]):
    print(f"{row['method']:9} {row['overrides'][:42]:42} {row['dofs']:7} {row['total_s']:9.3f} "
          f"{row['field_l2_error']:10.3e}")

check(all(row["status"] == "ok" for row in runs), "every run succeeded")
for method in methods:
    own = sorted((row for row in runs if row["method"] == method), key=lambda row: row["dofs"])
    check(own[-1]["field_l2_error"] < own[0]["field_l2_error"], f"{method}: more DOFs, a smaller L2 error")

# The Pareto front: in order of time, each run more accurate than every faster one.
front, best = [], float("inf")
for row in sorted(runs, key=lambda row: row["total_s"]):
    if row["field_l2_error"] < best:
        front.append(row)
        best = row["field_l2_error"]
print("\nPareto front (fastest first): " + ", ".join(f"{row['method']} ({row['dofs']} DOFs)" for row in front))
check(len(front) >= 1 and front[-1]["field_l2_error"] == min(row["field_l2_error"] for row in runs),
      "the front ends at the most accurate run")

figure, axes = plt.subplots(figsize=(6, 4))
for index, method in enumerate(methods):
    own = [row for row in runs if row["method"] == method]
    axes.loglog([row["total_s"] for row in own], [row["field_l2_error"] for row in own], "o", color=f"C{index}",
                label=method)
axes.step([row["total_s"] for row in front], [row["field_l2_error"] for row in front], "k--", where="post",
          label="Pareto front")
axes.set_xlabel("run time (s)")
axes.set_ylabel("L2 error against the exact solution")
axes.set_title("Half ball, manufactured solution")
axes.legend()
save(figure, options.out, "speed_accuracy")
finish()
