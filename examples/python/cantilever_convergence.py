#!/usr/bin/python3
"""The cantilever under its own weight with every method, refined three or four times.

A steel-like beam, L = 1 m, square section h = b = 0.1 m, E = 1 GPa, ν = 0.3,
ρ = 1000 kg/m³, clamped at x = 0, loaded by gravity: a distributed load q = ρ g b h.
Beam theory gives the tip deflection (Timoshenko, shear factor κ = 5/6):

    w = q L⁴ / (8 E I)  +  q L² / (2 κ G A),     I = b h³ / 12,  G = E / (2 (1 + ν))

The 3D solid differs from the beam by the clamp's Poisson constraint (about 1 %), so the
errors below are measured against a finer fem Hex20 run, and beam theory is checked
to within 2 %. Each method should converge: its error falls as its DOFs grow. (fcm's
cells on this box are fem's elements, none cut: their lines coincide.)

    /usr/bin/python3 examples/python/cantilever_convergence.py [--quick] [--out DIR]
"""
import numpy as np

from teaching import altfem, arguments, check, finish, plt, save, scene, tip

options = arguments(__doc__.splitlines()[0])

# Resolutions along the beam (n × n/10 × n/10 cells) for each method's own key.
sizes = [10, 20] if options.quick else [10, 20, 40]
methods = {
    "fem Hex20": ("fem", "discretization/fem/resolution", {}),
    "fcm Hex20": ("fcm", "discretization/fcm/resolution", {"discretization/fcm/cell": "hex20"}),
    "dg k = 2": ("dg", "discretization/dg/resolution", {"discretization/dg/degree": 2}),
    "harmonic": ("harmonic", "discretization/harmonic/convert/resolution", {}),
}

# Beam theory.
L, b, h, E, nu, rho, g = 1.0, 0.1, 0.1, 1e9, 0.3, 1000.0, 9.81
q, I, A, G = rho * g * b * h, b * h**3 / 12, b * h, E / (2 * (1 + nu))
timoshenko = q * L**4 / (8 * E * I) + q * L**2 / (2 * 5 / 6 * G * A)
print(f"beam theory: tip deflection {timoshenko:.6e} m (Euler-Bernoulli {q * L**4 / (8 * E * I):.6e} m)")

deflections = {}  # label -> [(dofs, tip deflection)]
for label, (method, key, fixed) in methods.items():
    for n in sizes:
        beam = scene("cantilever")
        for setting, value in fixed.items():
            beam.set(setting, value)
        beam.set(key, [n, max(1, n // 10), max(1, n // 10)])
        result = altfem.run(beam, method=method)
        w = -tip(result.frames[-1])[2]
        deflections.setdefault(label, []).append((result.summary["dofs"], w))
        print(f"{label:10} n = {n:3}: {result.summary['dofs']:7} DOFs, tip deflection {w:.6e} m")

finest = 2 * sizes[-1]
fine = scene("cantilever").set("discretization/fem/resolution", [finest, finest // 10, finest // 10])
reference = -tip(altfem.run(fine, method="fem").frames[-1])[2]
print(f"\nreference (fem Hex20, {finest} x {finest // 10} x {finest // 10}): {reference:.6e} m\n")
print(f"{'method':10} {'DOFs':>8} {'error':>10} {'rate':>6}")
figure, axes = plt.subplots(figsize=(6, 4))
for label, rows in deflections.items():
    dofs = np.array([row[0] for row in rows], dtype=float)
    errors = np.array([abs(row[1] - reference) / reference for row in rows])
    for i, (count, error) in enumerate(zip(dofs, errors)):
        # Convergence rate in h: error ~ h^r and DOFs ~ h^-3, so r = -3 d(log e)/d(log N).
        rate = -3 * np.log(errors[i] / errors[i - 1]) / np.log(dofs[i] / dofs[i - 1]) if i else np.nan
        print(f"{label:10} {int(count):8} {error:10.2e} {rate:6.2f}")
    check(np.all(np.diff(errors) < 0), f"{label}: the error falls at every refinement")
    axes.loglog(dofs, errors, "o-", label=label)
check(abs(reference - timoshenko) / timoshenko < 0.02,
      f"the reference is within 2 % of Timoshenko's beam ({abs(reference - timoshenko) / timoshenko:.2%})")
axes.set_xlabel("DOFs")
axes.set_ylabel("relative tip error")
axes.set_title("Cantilever under gravity")
axes.legend()
save(figure, options.out, "cantilever_convergence")
finish()
