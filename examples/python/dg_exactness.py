#!/usr/bin/python3
"""Why interior-penalty DG is consistent and Babuška–Zlámal is not
(Kaufmann et al. 2009, §4 and Fig. 1, here in 3D, as a scene built in Python).

Linear elasticity −div σ(u) = f on the unit cube, u = g on its whole boundary, with the
quadratic exact solution u = (y² + xz, x² − yz, xy + z²) (λ = 2, μ = 1.5: f = −μΔu −
(λ+μ)∇div u = (−3, −3, −10)), discretised by polynomials of degree k = 2 on each cell of a
3 × 3 × 3 grid. The exact solution lies in the discrete space. How the cells are glued:

  interior penalty (IP):  Σ_K ∫ σ(u):ε(v) − Σ_f ∫ ({σ(u)}n·[v] + {σ(v)}n·[u]) + Σ_f η_f ∫ [u]·[v]
  Babuška–Zlámal (BZ):    Σ_K ∫ σ(u):ε(v)                                  + Σ_f η_f ∫ [u]·[v]

The exact solution has no jumps and a single-valued traction, so it satisfies IP's
equations: IP reproduces it to round-off for every η. BZ lacks the traction terms: its
error is O(1/η), shrinking only as the penalty grows (and the matrix's condition with it).

    /usr/bin/python3 examples/python/dg_exactness.py [--quick] [--out DIR]
"""
import numpy as np

from teaching import altfem, arguments, check, finish, plt, save

options = arguments(__doc__.splitlines()[0])
lam, mu = 2.0, 1.5
exact = ["y^2 + x*z", "x^2 - y*z", "x*y + z^2"]
cube = {
    "name": "quadratic_cube",
    "geometry": {"shape": {"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}},
    # Young's modulus and Poisson's ratio of these Lamé parameters.
    "material": {"model": "linear", "youngs_modulus": mu * (3 * lam + 2 * mu) / (lam + mu),
                 "poisson_ratio": lam / (2 * (lam + mu)), "density": 1},
    "boundary_conditions": [{"type": "dirichlet", "region": {"box": {"min": [-1, -1, -1], "max": [2, 2, 2]}},
                             "motion": {"kind": "field", "displacement": exact}}],
    "loads": {"body_force": ["-3", "-3", "-10"]},
    "exact_displacement": exact,
    "time": {"static": True},
    "solver": {"tolerance": 1e-12},
    "discretization": {"dg": {"mesh": "grid", "element": "hex8", "resolution": [3, 3, 3], "degree": 2,
                              "penalty": {"convention": "kaufmann", "double_until_definite": False}}},
}

penalties = [1e2, 1e4] if options.quick else [1e1, 1e2, 1e3, 1e4, 1e5]
errors = {"interior_penalty": [], "babuska_zlamal": []}
print(f"{'eta':>8} {'IP L2 error':>14} {'BZ L2 error':>14}")
for eta in penalties:
    for flux in errors:
        scene = altfem.Scene(cube).set("discretization/dg/flux", flux).set("discretization/dg/penalty/value", eta)
        errors[flux].append(altfem.run(scene, method="dg").summary["field_errors"]["relative_l2"])
    print(f"{eta:8.0e} {errors['interior_penalty'][-1]:14.2e} {errors['babuska_zlamal'][-1]:14.2e}")

check(max(errors["interior_penalty"]) < 1e-9, "IP reproduces the quadratic solution to round-off at every eta")
slope = np.polyfit(np.log(penalties), np.log(errors["babuska_zlamal"]), 1)[0]
check(-1.2 < slope < -0.8, f"BZ's error falls like 1/eta (slope {slope:.2f} in log-log)")
check(min(errors["babuska_zlamal"]) > 1e3 * max(errors["interior_penalty"]), "BZ stays far from exact")

figure, axes = plt.subplots(figsize=(6, 4))
axes.loglog(penalties, errors["babuska_zlamal"], "o-", label="Babuska-Zlamal")
axes.loglog(penalties, np.maximum(errors["interior_penalty"], 1e-16), "s-", label="interior penalty")
axes.set_xlabel("penalty eta")
axes.set_ylabel("relative L2 error")
axes.set_title("A quadratic solution, dg k = 2 on 3 x 3 x 3 cells")
axes.legend()
save(figure, options.out, "dg_exactness")
finish()
