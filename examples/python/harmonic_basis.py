#!/usr/bin/python3
"""The harmonic basis of one non-convex polyhedral element (Martin et al. 2008, §4–5, Fig. 2).

A polyhedron has no reference element and no Lagrange basis. Martin et al. build one node
function N_i per vertex that is harmonic inside (ΔN_i = 0) and on the boundary equals a
2D harmonic coordinate of each face: 1 at vertex i, 0 at the others, linear along edges.
Constants and linear fields are harmonic, so Σ N_i = 1 and Σ N_i x_i = x hold exactly,
and by the maximum principle 0 ≤ N_i ≤ 1. altfem fits each N_i by the method of
fundamental solutions; here on an L-shaped prism, where no barycentric or trilinear
construction applies. The figure shows two of them on the slice z = 0.35.

    /usr/bin/python3 examples/python/harmonic_basis.py [--quick] [--out DIR]
"""
import numpy as np

from teaching import altfem, arguments, check, finish, plt, save

options = arguments(__doc__.splitlines()[0])

# The prism of height 0.7 over L = [0,2]×[0,1] ∪ [0,1]×[0,2]: bottom vertices 0–5 along the
# outline (counter-clockwise seen from above), top vertices 6–11 above them.
outline = np.array([[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]], dtype=float)
vertices = np.vstack([np.c_[outline, np.zeros(6)], np.c_[outline, np.full(6, 0.7)]])
faces = [[5, 4, 3, 2, 1, 0], [6, 7, 8, 9, 10, 11]] + [[k, (k + 1) % 6, (k + 1) % 6 + 6, k + 6] for k in range(6)]

basis = altfem.harmonic.basis(vertices, faces)
print(f"L-shaped prism: {basis.node_count} nodes, {len(basis.centres)} kernel centres, "
      f"boundary fit RMS {basis.boundary_residual:.2e}")

# Samples on the slice z = 0.35, inside the element only.
n = 40 if options.quick else 100
x, y = np.meshgrid(np.linspace(0.01, 1.99, n), np.linspace(0.01, 1.99, n))
points = np.c_[x.ravel(), y.ravel(), np.full(x.size, 0.35)]
inside = altfem.harmonic.winding_number(vertices, faces, points) > 0.5
values = basis.values(points[inside])  # (#inside, 12)

unity = np.abs(values.sum(axis=1) - 1).max()
linear = np.abs(values @ vertices - points[inside]).max()
kronecker = np.abs(basis.values(vertices) - np.eye(12))
print(f"{inside.sum()} samples inside the slice")
print(f"max |sum_i N_i - 1|              {unity:.2e}")
print(f"max |sum_i N_i x_i - x|          {linear:.2e}")
print(f"max |N_i(x_j) - delta_ij|        {kronecker.max():.2e} (the re-entrant vertices 3 and 9: "
      f"{kronecker[[3, 9]].max():.2e}, where the exact N_i have singular gradients)")
print(f"range of the N_i on the slice    [{values.min():.4f}, {values.max():.4f}]")

check(unity < 1e-10, "partition of unity to round-off")
check(linear < 1e-10, "linear fields reproduced to round-off")
check(np.delete(kronecker, [3, 9], axis=0).max() < 4e-2, "N_i(x_j) = delta_ij to 4e-2 away from the re-entrant edge")
check(values.min() > -4e-2 and values.max() < 1 + 4e-2, "0 <= N_i <= 1 to 4e-2 (maximum principle)")

figure, axes = plt.subplots(1, 2, figsize=(9, 4))
for axis, node in zip(axes, [0, 3]):
    field = np.full(x.size, np.nan)
    field[inside] = values[:, node]
    contour = axis.contourf(x, y, field.reshape(x.shape), levels=np.linspace(-0.05, 1.05, 23), cmap="viridis")
    axis.plot(*np.vstack([outline, outline[:1]]).T, "k-")
    axis.plot(*outline[node], "ro")
    axis.set_title(f"N_{node} on z = 0.35" + (" (re-entrant corner)" if node == 3 else ""))
    axis.set_aspect("equal")
figure.colorbar(contour, ax=axes)
save(figure, options.out, "harmonic_basis")
finish()
