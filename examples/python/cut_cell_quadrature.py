#!/usr/bin/python3
"""One cut Hex20 cell of the Finite Cell Method and its two quadrature rules
(Longva et al. 2020, §4.5–4.6, Figs. 3–4).

A cell of the background grid that the sphere's surface cuts is integrated only over its
inside part. The initial rule puts a Gauss rule on every embedded tetrahedron inside the
cell (many points); the simplified rule keeps at most C(m+3, 3) of them, with new
positive weights, such that every monomial of degree ≤ m integrates exactly as before.
Fewer points means cheaper assembly at every Newton iteration, for a one-time cost.

    /usr/bin/python3 examples/python/cut_cell_quadrature.py [--quick] [--out DIR]
"""
import itertools
import math

import numpy as np

from teaching import altfem, arguments, check, finish, plt, save, scene

options = arguments(__doc__.splitlines()[0])
m = 3 if options.quick else 4

rules = altfem.quadrature.cut_cell(scene("sphere"), cell=(0, 1, 1), resolution=3, order=m)
initial, simplified = rules["initial"], rules["simplified"]
print(f"cell (0, 1, 1) of a 3 x 3 x 3 grid over the sphere: clipped volume {rules['clipped_volume']:.6e} m^3")
print(f"initial rule {len(initial['weights'])} points, simplified {len(simplified['weights'])} points "
      f"(at most C(m+3, 3) = {math.comb(m + 3, 3)} for m = {m})")

# Every monomial x^a y^b z^c with a + b + c <= m, in coordinates centred and scaled on the
# cell's points so that the moments are of order one.
centre = initial["points"].mean(axis=0)
scale = np.abs(initial["points"] - centre).max()
print(f"\n{'monomial':>10} {'initial':>14} {'simplified':>14} {'rel. error':>11}")
largest = 0.0
for a, b, c in itertools.product(range(m + 1), repeat=3):
    if a + b + c > m:
        continue
    moments = []
    for rule in (initial, simplified):
        x, y, z = ((rule["points"] - centre) / scale).T
        moments.append(np.sum(rule["physical_weights"] * x**a * y**b * z**c))
    error = abs(moments[1] - moments[0]) / max(abs(moments[0]), rules["clipped_volume"])
    largest = max(largest, error)
    if a + b + c <= 1 or (a, b, c) == (m, 0, 0):
        print(f"{f'x{a}y{b}z{c}':>10} {moments[0]:14.6e} {moments[1]:14.6e} {error:11.1e}")
print(f"largest relative moment error over all {math.comb(m + 3, 3)} monomials: {largest:.1e}")

check(len(simplified["weights"]) <= math.comb(m + 3, 3), "the simplified rule has at most C(m+3, 3) points")
check(np.all(simplified["physical_weights"] > 0), "its weights are positive")
check(largest < 1e-10, "it integrates every monomial of degree <= m as the initial rule does")

# Fig. 4: points of the simplified rules for strengths 1..m, on this cell type.
print(f"\nFig. 4 (hex20, strengths 1..{m}): points after simplification, and the largest error")
for row in altfem.quadrature.monomials("hex20", order=m):
    print(f"  m = {row['order']}: {row['simplified']['points']:3} points of at most {row['basis_size']:3}, "
          f"error {row['simplified']['max_relative_error']:.1e}")
    check(row["simplified"]["points"] <= row["basis_size"], f"m = {row['order']}: within C(m+3, 3)")

figure = plt.figure(figsize=(6, 5))
axes = figure.add_subplot(projection="3d")
axes.scatter(*initial["points"].T, s=2, alpha=0.3, label=f"initial ({len(initial['weights'])})")
sizes = 400 * simplified["physical_weights"] / simplified["physical_weights"].max()
axes.scatter(*simplified["points"].T, s=sizes, color="C3", label=f"simplified ({len(simplified['weights'])})")
axes.set_title(f"Cut Hex20 cell, m = {m}: marker area ~ weight")
axes.legend()
save(figure, options.out, "cut_cell_quadrature")
finish()
