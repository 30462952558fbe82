#!/usr/bin/python3
"""Locking: a nearly incompressible cube hanging under its own weight
(Kaufmann et al. 2009, §9.5 and Fig. 9).

As Poisson's ratio ν → 0.5, λ/μ = 2ν/(1 − 2ν) grows without bound and the body resists any
change of volume. Linear tetrahedra (Tet4) have one strain per element; keeping every
element's volume fixed leaves them almost no way to deform, and the body "locks": it sags
far less than it should. Higher-order elements (Hex20, fcm's Hex20 cells) and
discontinuous Galerkin (enough extra freedom per element) do not.

The unit cube hangs from its top face, E = 1e5 Pa, ρ = 1000 kg/m³, 5 × 5 × 5 cells (the
Tet4 and dg meshes: 750 tetrahedra, the paper's size). Each method's sag (the bottom
face's mean downward displacement) is divided by that of a fine Tet10 run at the same ν.

    /usr/bin/python3 examples/python/locking.py [--quick] [--out DIR]
"""
import numpy as np

from teaching import altfem, arguments, check, finish, plt, save, scene

options = arguments(__doc__.splitlines()[0])
ratios = [0.3, 0.499] if options.quick else [0.3, 0.4, 0.45, 0.49, 0.499]
methods = {
    "fem Tet4": ("fem", {}),
    "fem Hex20": ("fem", {"discretization/fem/element": "hex20"}),
    "fcm Hex20": ("fcm", {}),
    "dg k = 2 (Tet4 mesh)": ("dg", {}),
}


def sag(method, settings, nu):
    cube = scene("suspended_cube").set("material/poisson_ratio", nu)
    for key, value in settings.items():
        cube.set(key, value)
    frame = altfem.run(cube, method=method).frames[-1]
    bottom = np.abs(frame.surface_vertices[:, 2]) < 1e-9
    return -frame.surface_displacement[bottom, 2].mean()


fractions = {label: [] for label in methods}
print(f"{'nu':>6} {'reference (m)':>14}" + "".join(f"{label:>22}" for label in methods))
for nu in ratios:
    reference = sag("fem", {"discretization/fem/element": "tet10", "discretization/fem/resolution": [10, 10, 10]}, nu)
    row = f"{nu:6.3f} {reference:14.4e}"
    for label, (method, settings) in methods.items():
        fractions[label].append(sag(method, settings, nu) / reference)
        row += f"{fractions[label][-1]:21.1%} "
    print(row)

tet4 = fractions["fem Tet4"]
check(tet4[-1] < tet4[0] - 0.1,
      f"Tet4 locks: {tet4[0]:.0%} of the sag at nu = {ratios[0]}, {tet4[-1]:.0%} at {ratios[-1]}")
for label in ("fem Hex20", "fcm Hex20", "dg k = 2 (Tet4 mesh)"):
    check(min(fractions[label]) > 0.9, f"{label} does not lock: within 10 % of the reference at every nu")

figure, axes = plt.subplots(figsize=(6, 4))
for label, values in fractions.items():
    axes.plot(ratios, values, "o-", label=label)
axes.set_xlabel("Poisson's ratio")
axes.set_ylabel("sag / fine Tet10 sag")
axes.set_title("Suspended cube: locking as nu -> 0.5")
axes.legend()
save(figure, options.out, "locking")
finish()
