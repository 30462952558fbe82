#!/usr/bin/python3
"""Writes the pencil scenes (issue #33; Kaufmann et al. 2009 §9.4, Fig. 10: a pencil of
a single convex element sharpened by repeated cuts): scenes/pencil.json (50 cuts in 80
steps, a compare block over all four methods), or with --cuts a benchmark variant (e.g.
500 cuts in 600 steps: the time per cut against the time per step).

A 0.1 x 0.1 x 1 m block held at its base z = 0 and pulled sideways by gravity is cut
by planes through points on its axis near the tip, each tilted 14 degrees from the axis
(a cone's tangent planes) and turned about the axis by a little more than a seventh of a
turn from the last, the apex sinking from z = 0.98 to 0.92 as the run goes on, so the tip
is sharpened to a point from every side. Each cut acts on the piece holding the base
(`piece_at`): the chips it severs are left whole and fall away.

Usage: bench/make_pencil_scenes.py [--cuts 500 --steps 600 --out /tmp/pencil_500.json]
"""
import argparse
import json
import math


def pencil(name, cuts, steps, compare):
    events = []
    half_angle = math.radians(14)
    for k in range(cuts):
        turn = 2 * math.pi * k * (1 / 7 + 0.013)
        depth = 0.02 + 0.06 * k / (cuts - 1)
        events.append({"time": round((k + 1) * steps * 0.005 * 0.8 / cuts, 9),
                       "cut": {"plane": {"point": [0.05, 0.05, round(1 - depth, 9)],
                                         "normal": [round(math.cos(turn), 12), round(math.sin(turn), 12),
                                                    round(math.tan(half_angle), 12)]},
                               "piece_at": [0.05, 0.05, 0]}})
    scene = {
        "name": name,
        "geometry": {"shape": {"box": {"min": [0, 0, 0], "max": [0.1, 0.1, 1]}}},
        "material": {"model": "linear", "youngs_modulus": 1e7, "poisson_ratio": 0.3, "density": 700},
        "boundary_conditions": [{"type": "dirichlet", "name": "hand",
                                 "region": {"box": {"min": [-1, -1, -1], "max": [2, 2, 0]}}}],
        "loads": {"gravity": [0, -9.81, 0]},
        "time": {"dt": 0.005, "steps": steps},
        "events": events,
        "discretization": {
            "dg": {"degree": 2, "resolution": [1, 1, 1]},
            # Ten cubes, not one cell: the one cell, fitted again at each cut, fits the
            # sharpened tip's small faces poorly (its kernels lie a fifth of its 1 m length
            # out), so a cut's nodal values made a field of up to 2.2 times the energy, and
            # the 500-cut variant's state exploded at step 34; on the cubes a cut's jump
            # stays below 1e-3 of the energy, at the same cost a cut (docs/performance.md).
            "harmonic": {"mesh": "convert", "convert": {"element": "hex8", "mesh": "grid", "resolution": [1, 1, 10]}},
            "fem": {"element": "hex20", "mesh": "grid", "resolution": [1, 1, 4], "cut_stabilization": 1e-6},
            "fcm": {"cell": "hex20", "resolution": [1, 1, 4]},
        },
    }
    if compare:
        scene["compare"] = {"methods": ["dg", "harmonic", "fem", "fcm"],
                            "reference": {"method": "dg", "set": {"discretization/dg/resolution": [2, 2, 8]}}}
    return scene


def write(path, scene):
    with open(path, "w") as stream:
        json.dump(scene, stream, indent=1)
        stream.write("\n")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cuts", type=int, default=50)
    parser.add_argument("--steps", type=int, default=80)
    parser.add_argument("--out", default="scenes/pencil.json")
    arguments = parser.parse_args()
    shipped = arguments.cuts == 50 and arguments.steps == 80
    write(arguments.out, pencil("pencil" if shipped else "pencil_%d" % arguments.cuts, arguments.cuts,
                                arguments.steps, shipped))
