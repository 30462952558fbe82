#!/usr/bin/python3
"""Writes data/volume/cook_membrane_tet10.msh: Cook's membrane (Cook 1974), the tapered
panel (0,0)-(48,44)-(48,60)-(0,44) extruded over z in [0, 1], as Tet10 cells (Gmsh MSH
2.2 ASCII). An n x n grid of the unit square is mapped bilinearly onto the panel, each
cell a straight-sided hexahedron split into six tetrahedra about its main diagonal
(the Kuhn split, conforming between cells); mid-nodes at edge midpoints.

Usage: scripts/make_cook_membrane_mesh.py [n] [output]   (default 16, the shipped mesh)
"""
import sys


def panel(xi, eta):
    # Bottom edge (0,0)-(48,44), top edge (0,44)-(48,60).
    return 48.0 * xi, 44.0 * xi + eta * (44.0 - 28.0 * xi)


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 16
    output = sys.argv[2] if len(sys.argv) > 2 else "data/volume/cook_membrane_tet10.msh"
    nodes = []
    index = {}

    def corner(i, j, k):
        key = ("c", i, j, k)
        if key not in index:
            x, y = panel(i / n, j / n)
            nodes.append((x, y, float(k)))
            index[key] = len(nodes)
        return index[key]

    def midpoint(a, b):
        key = ("m",) + tuple(sorted((a, b)))
        if key not in index:
            nodes.append(tuple((p + q) / 2 for p, q in zip(nodes[a - 1], nodes[b - 1])))
            index[key] = len(nodes)
        return index[key]

    # The six tetrahedra of the Kuhn split of a cube with corners c[ijk], positively
    # oriented: paths from corner 000 to 111 through one, then two, raised indices.
    paths = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]
    tets = []
    for i in range(n):
        for j in range(n):
            cell = lambda d: corner(i + d[0], j + d[1], d[2])
            for path in paths:
                step = [0, 0, 0]
                vertices = [cell(step)]
                for axis in path:
                    step[axis] = 1
                    vertices.append(cell(step))
                tets.append(vertices)
    elements = []
    for v in tets:
        # Orient positively (the bilinear map keeps orientation, so this only fixes the
        # path parity).
        a, b, c, d = (nodes[x - 1] for x in v)
        e1 = [b[t] - a[t] for t in range(3)]
        e2 = [c[t] - a[t] for t in range(3)]
        e3 = [d[t] - a[t] for t in range(3)]
        volume = (e1[0] * (e2[1] * e3[2] - e2[2] * e3[1]) - e1[1] * (e2[0] * e3[2] - e2[2] * e3[0])
                  + e1[2] * (e2[0] * e3[1] - e2[1] * e3[0]))
        if volume < 0:
            v = [v[0], v[2], v[1], v[3]]
        p0, p1, p2, p3 = v
        # Gmsh's 10-node tetrahedron: edges 01, 12, 20, 03, 23, 13.
        mids = [midpoint(p0, p1), midpoint(p1, p2), midpoint(p2, p0), midpoint(p0, p3), midpoint(p2, p3),
                midpoint(p1, p3)]
        elements.append(v + mids)
    with open(output, "w") as out:
        out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for number, (x, y, z) in enumerate(nodes, 1):
            out.write("%d %.17g %.17g %.17g\n" % (number, x, y, z))
        out.write("$EndNodes\n$Elements\n%d\n" % len(elements))
        for number, element in enumerate(elements, 1):
            out.write("%d 11 2 1 1 %s\n" % (number, " ".join(str(x) for x in element)))
        out.write("$EndElements\n")


main()
