#!/usr/bin/python3
"""Writes the manufactured solutions on a curved domain: scenes/manufactured_half_ball.json
(smooth) and scenes/manufactured_half_ball_peak.json (a sharp peak inside the ball).

The half-ball x² + y² + z² ≤ 1, z ≥ 0 is clamped on its flat face z = 0 by the field
motion u* (zero there) and loaded by the body force f = −div σ(u*) and, on the curved
part, by the traction σ(u*)·n, n the outward unit normal (`nx`, `ny`, `nz` in the
scene's expressions). Then u* is the exact solution on whatever polyhedron a method
integrates, since its tractions use that polyhedron's own normals, and the solution has
no singularity where the clamped and free parts meet at 90°: Longva et al. 2020's
Fig. 10 study (§6.6) with an exact answer.

The smooth solution (sines and cosines) spreads its error over the whole ball, which is
where uniform grids do best. The peak, z·exp(−β|x − c|²) times a linear vector, puts
almost all of its error near c, away from both the clamp and the curved surface: the
classic test of adaptive refinement (issue #34), where a uniform grid refines the
whole ball for a region a few cells wide. Needs sympy (Debian: python3-sympy).

    /usr/bin/python3 scripts/manufactured_half_ball.py
"""
import json
import pathlib

import sympy as sp

x, y, z, a, lam, mu, nx, ny, nz = sp.symbols("x y z a lambda mu nx ny nz")
beta, cx, cy, cz = sp.symbols("beta cx cy cz")
position = [x, y, z]
SCENES = pathlib.Path(__file__).resolve().parent.parent / "scenes"
HALF_BALL = {"shape": {"intersection": [{"sphere": {"centre": [0, 0, 0], "radius": 1}},
                                        {"box": {"min": [-2, -2, 0], "max": [2, 2, 2]}}]}}


def expressions(vector, simplify):
    """muParser text of a sympy vector (powers as ^)."""
    return [str(sp.simplify(c) if simplify else sp.expand(c)).replace("**", "^") for c in vector]


def loads(exact, simplify_traction):
    """The body force −div σ(u*) and the traction σ(u*)·n of linear elasticity."""
    gradient = exact.jacobian(position)
    strain = (gradient + gradient.T) / 2
    stress = lam * strain.trace() * sp.eye(3) + 2 * mu * strain
    body_force = -sp.Matrix([sum(sp.diff(stress[i, j], position[j]) for j in range(3)) for i in range(3)])
    traction = stress * sp.Matrix([nx, ny, nz])
    return expressions(body_force, True), expressions(traction, simplify_traction)


# The clamp and the traction meet on one plane just above the flat face, so that each
# boundary face is one or the other. A region holds a face within 1e-6 of the bounds'
# diagonal (3e-6 here), so the earlier pair z <= 0 and z >= 1e-6 both held the flat face:
# dg, which holds it weakly, also loaded it, and missed a quadratic exact solution by 2-4 %
# at k = 2 (Mesh_3's flat face is flat to about 1e-7 and its rim is rounded, so a plane
# just above z = 0 is safer than one on it). A face on either side is exact for u*: nodal
# and weak conditions take u*, tractions σ(u*) n.
SPLIT = 1e-3


def write(name, exact, constants, discretization, compare, simplify_traction=False, events=None):
    displacement = expressions(exact, True)
    body_force, traction = loads(exact, simplify_traction)
    scene = {
        "name": name,
        "geometry": HALF_BALL,
        # λ = 15, μ = 10
        "material": {"model": "linear", "youngs_modulus": 26, "poisson_ratio": 0.3, "density": 1},
        "constants": constants,
        "boundary_conditions": [{"type": "dirichlet",
                                 "region": {"half_space": {"point": [0, 0, SPLIT], "normal": [0, 0, 1]}},
                                 "motion": {"kind": "field", "displacement": displacement}}],
        "loads": {"body_force": body_force,
                  "traction": [{"region": {"half_space": {"point": [0, 0, SPLIT], "normal": [0, 0, -1]}},
                                "traction": traction}]},
        "exact_displacement": displacement,
        "time": {"static": True},
        "solver": {"tolerance": 1e-10},
        "discretization": discretization,
    }
    if events:
        scene["events"] = events
    scene["compare"] = compare
    path = SCENES / f"{name}.json"
    path.write_text(json.dumps(scene, indent=2) + "\n")
    print(f"wrote {path}")


write("manufactured_half_ball",
      sp.Matrix([a * z * sp.sin(2 * x) * sp.cos(y), a * z * sp.cos(x + 2 * y), a * z * (z + sp.sin(x * y))]),
      {"a": 0.01, "lambda": 15, "mu": 10},
      {"fem": {"element": "tet10", "mesh": "tetrahedralize", "max_cell_size": 0.2},
       "fcm": {"cell": "hex20", "resolution": [8, 8, 4], "embedded_cell_size": 0.1},
       "dg": {"degree": 2, "element": "tet4", "mesh": "tetrahedralize", "max_cell_size": 0.25},
       "harmonic": {"convert": {"element": "tet4", "mesh": "tetrahedralize", "max_cell_size": 0.2}}},
      {"methods": ["fem", "fcm", "dg", "harmonic"],
       "sweeps": {"discretization/fem/max_cell_size": [0.4, 0.2],
                  "discretization/fcm/cell": ["hex8", "hex20"],
                  "discretization/fcm/resolution": [[4, 4, 2], [8, 8, 4]],
                  "discretization/dg/max_cell_size": [0.4, 0.25],
                  "discretization/harmonic/convert/max_cell_size": [0.3, 0.15]},
       "reference": {"method": "fcm", "set": {"discretization/fcm/resolution": [16, 16, 8]}}})

# The peak: width 1/sqrt(2β) ≈ 0.11 around c, 0.4 above the clamp and 0.54 inside the
# sphere, so the field there is below exp(−β·0.4²) ≈ 2e-3 of its peak.
peak = sp.exp(-beta * ((x - cx) ** 2 + (y - cy) ** 2 + (z - cz) ** 2))
cycles = lambda count: [{"time": 0, "refine": {"criterion": "error_indicator", "fraction": 0.5, "max_level": 10,
                                               "cycles": count}}]
write("manufactured_half_ball_peak",
      sp.Matrix([a * z * peak, a * z * (1 - x) * peak, a * z * (1 + y) * peak]),
      {"a": 0.01, "lambda": 15, "mu": 10, "beta": 40, "cx": 0.2, "cy": 0.1, "cz": 0.4},
      # Both dg and harmonic on the sliced grid: hexahedral cells they can split 1 -> 8.
      {"fem": {"element": "tet10", "mesh": "tetrahedralize", "max_cell_size": 0.2},
       "fcm": {"cell": "hex20", "resolution": [4, 4, 2], "embedded_cell_size": 0.1},
       "dg": {"degree": 2, "mesh": "slice", "slice": {"resolution": 4}},
       "harmonic": {"mesh": "slice", "slice": {"resolution": 4}}},
      {"methods": ["fcm", "dg", "harmonic"],
       "sweeps": [{"discretization/fcm/resolution": [[4, 4, 2], [8, 8, 4], [16, 16, 8]],
                   "discretization/dg/slice/resolution": [4, 8, 16],
                   "discretization/harmonic/slice/resolution": [4, 8, 16]},
                  {"events": [cycles(2), cycles(4)]}],
       "reference": {"method": "fcm", "set": {"discretization/fcm/resolution": [16, 16, 8]}}},
      simplify_traction=True)
