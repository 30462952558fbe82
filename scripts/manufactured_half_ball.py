#!/usr/bin/python3
"""Writes scenes/manufactured_half_ball.json: a manufactured solution on a curved domain.

The half-ball x² + y² + z² ≤ 1, z ≥ 0 is clamped on its flat face z = 0 by the field
motion u* (zero there) and loaded by the body force f = −div σ(u*) and, on the curved
part, by the traction σ(u*)·n, n the outward unit normal (`nx`, `ny`, `nz` in the
scene's expressions). Then u* is the exact solution on whatever polyhedron a method
integrates, since its tractions use that polyhedron's own normals, and the solution has
no singularity where the clamped and free parts meet at 90°: Longva et al. 2020's
Fig. 10 study (§6.6) with an exact answer. Needs sympy (Debian: python3-sympy).

    /usr/bin/python3 scripts/manufactured_half_ball.py
"""
import json
import pathlib

import sympy as sp

x, y, z, a, lam, mu, nx, ny, nz = sp.symbols("x y z a lambda mu nx ny nz")
position = [x, y, z]
exact = sp.Matrix([a * z * sp.sin(2 * x) * sp.cos(y), a * z * sp.cos(x + 2 * y), a * z * (z + sp.sin(x * y))])
gradient = exact.jacobian(position)
strain = (gradient + gradient.T) / 2
stress = lam * strain.trace() * sp.eye(3) + 2 * mu * strain  # linear elasticity
body_force = -sp.Matrix([sum(sp.diff(stress[i, j], position[j]) for j in range(3)) for i in range(3)])
traction = stress * sp.Matrix([nx, ny, nz])


def expressions(vector, simplify):
    """muParser text of a sympy vector (powers as ^)."""
    return [str(sp.simplify(c) if simplify else sp.expand(c)).replace("**", "^") for c in vector]


displacement = expressions(exact, True)
scene = {
    "name": "manufactured_half_ball",
    "geometry": {"shape": {"intersection": [{"sphere": {"centre": [0, 0, 0], "radius": 1}},
                                            {"box": {"min": [-2, -2, 0], "max": [2, 2, 2]}}]}},
    # λ = 15, μ = 10
    "material": {"model": "linear", "youngs_modulus": 26, "poisson_ratio": 0.3, "density": 1},
    "constants": {"a": 0.01, "lambda": 15, "mu": 10},
    "boundary_conditions": [{"type": "dirichlet", "region": {"half_space": {"point": [0, 0, 0], "normal": [0, 0, 1]}},
                             "motion": {"kind": "field", "displacement": displacement}}],
    "loads": {"body_force": expressions(body_force, True),
              "traction": [{"region": {"half_space": {"point": [0, 0, 1e-6], "normal": [0, 0, -1]}},
                            "traction": expressions(traction, False)}]},
    "exact_displacement": displacement,
    "time": {"static": True},
    "solver": {"tolerance": 1e-10},
    "discretization": {
        "fem": {"element": "tet10", "mesh": "tetrahedralize", "max_cell_size": 0.2},
        "fcm": {"cell": "hex20", "resolution": [8, 8, 4], "embedded_cell_size": 0.1},
        "dg": {"degree": 2, "element": "tet4", "mesh": "tetrahedralize", "max_cell_size": 0.25},
        "harmonic": {"convert": {"element": "tet4", "mesh": "tetrahedralize", "max_cell_size": 0.2}},
    },
    "compare": {
        "methods": ["fem", "fcm", "dg", "harmonic"],
        "sweeps": {"discretization/fem/max_cell_size": [0.4, 0.2],
                   "discretization/fcm/cell": ["hex8", "hex20"],
                   "discretization/fcm/resolution": [[4, 4, 2], [8, 8, 4]],
                   "discretization/dg/max_cell_size": [0.4, 0.25],
                   "discretization/harmonic/convert/max_cell_size": [0.3, 0.15]},
        "reference": {"method": "fcm", "set": {"discretization/fcm/resolution": [16, 16, 8]}},
    },
}
path = pathlib.Path(__file__).resolve().parent.parent / "scenes" / "manufactured_half_ball.json"
path.write_text(json.dumps(scene, indent=2) + "\n")
print(f"wrote {path}")
