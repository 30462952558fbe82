#!/usr/bin/python3
"""Writes the blade surfaces of the surface-blade measurements (issue #33: a cut event's
`surface`, docs/scene-schema.md "Events"), for tests/verify/events/scenes/cantilever_cut.json
and a unit cube:

- curved.obj: a sheet bent about y (a cylinder of radius 0.3 about the line x = 0.8,
  z = -0.2, from 100 to 160 degrees, y from -0.1 to 0.2) in 16 x 4 quadrilaterals, 128
  triangles: it cuts the cantilever from below and ends inside it, near its top;
- ball<L>.off, L = 1, 2: an icosphere of 80 or 320 triangles, radius 0.3 about (0.5, 0.5,
  0.5): closed, many triangles meeting at each vertex.

Usage: bench/make_surface_blades.py --out /tmp/blades
Then, for example (M: dg, harmonic, fcm, fem):
  build/bin/altfem run tests/verify/events/scenes/cantilever_cut.json --method M \
    --set 'events=[{"time": 0.02, "cut": {"surface": "/tmp/blades/curved.obj"}}]' --out out/curved_M
"""
import argparse
import math
import os


def curved_sheet(path, around=16, across=4):
    vertices, triangles = [], []
    for i in range(around + 1):
        angle = math.radians(100 + 60 * i / around)
        for j in range(across + 1):
            vertices.append((0.8 + 0.3 * math.cos(angle), -0.1 + 0.3 * j / across, -0.2 + 0.3 * math.sin(angle)))
    for i in range(around):
        for j in range(across):
            corner = i * (across + 1) + j
            triangles.append((corner, corner + across + 1, corner + across + 2))
            triangles.append((corner, corner + across + 2, corner + 1))
    with open(path, "w") as out:
        out.writelines("v %.12g %.12g %.12g\n" % v for v in vertices)
        out.writelines("f %d %d %d\n" % tuple(k + 1 for k in t) for t in triangles)


def icosphere(path, level):
    golden = (1 + 5 ** 0.5) / 2
    points = [(-1, golden, 0), (1, golden, 0), (-1, -golden, 0), (1, -golden, 0), (0, -1, golden), (0, 1, golden),
              (0, -1, -golden), (0, 1, -golden), (golden, 0, -1), (golden, 0, 1), (-golden, 0, -1), (-golden, 0, 1)]
    points = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in points]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        middle, finer = {}, []

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                p = [(points[a][k] + points[b][k]) / 2 for k in range(3)]
                norm = math.sqrt(sum(x * x for x in p))
                points.append(tuple(x / norm for x in p))
                middle[key] = len(points) - 1
            return middle[key]

        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = finer
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
        out.writelines("%.15g %.15g %.15g\n" % tuple(0.5 + 0.3 * x for x in p) for p in points)
        out.writelines("3 %d %d %d\n" % f for f in faces)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="folder to write the blades to")
    folder = parser.parse_args().out
    os.makedirs(folder, exist_ok=True)
    curved_sheet(os.path.join(folder, "curved.obj"))
    for level in (1, 2):
        icosphere(os.path.join(folder, "ball%d.off" % level), level)


if __name__ == "__main__":
    main()
