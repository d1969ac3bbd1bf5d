#!/usr/bin/env python3
"""Writes a JSON scene of N random analytic objects of every kind (spheres,
boxes, triangles, quadric presets, polygons, convex polyhedra), some
transformed, and four small teapots of Bezier patches (two by Newton
iteration, two by subdivision), for prism-bench accel's agreement check
across the structures:

    python3 benchmarks/kinds_scene.py 600 > kinds.json
    build/benchmarks/prism-bench accel kinds.json --structures bvh,octree,bsp,none
"""
import json
import math
import os
import random
import sys

TEAPOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "patches", "teapot.bpt")


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 600
    rng = random.Random(20261203)
    objects = []
    for i in range(count):
        c = [rng.uniform(-4, 4) for _ in range(3)]
        s = rng.uniform(0.05, 0.3)
        move = {"translate": c}
        kind = i % 9
        if kind == 0:
            objects.append({"type": "sphere", "center": c, "radius": s})
        elif kind == 1:
            objects.append({"type": "box", "min": [x - s for x in c], "max": [x + s for x in c]})
        elif kind == 2:
            objects.append({"type": "triangle", "vertices": [[x + rng.uniform(-s, s) for x in c] for _ in range(3)]})
        elif kind == 3:
            objects.append({"type": rng.choice(["cylinder", "cone", "paraboloid"]), "radius": s, "height": 2 * s,
                            "capped": rng.random() < 0.5,
                            "transform": [{"rotate": {"axis": [rng.uniform(-1, 1), 1, 0], "angle": rng.uniform(0, 90)}},
                                          move]})
        elif kind == 4:
            objects.append({"type": "ellipsoid", "radii": [s, 1.5 * s, 0.7 * s], "transform": move})
        elif kind == 5:
            objects.append({"type": "hyperboloid", "sheets": rng.choice([1, 2]), "radius": 0.5 * s, "vertex": 0.4 * s,
                            "top_radius": s, "height": s, "transform": move})
        elif kind == 6:
            n = rng.randint(3, 12)
            star = n % 2 == 0 and rng.random() < 0.5
            objects.append({"type": "polygon", "inside_test": rng.choice(["crossing", "radial"]),
                            "vertices": [[c[0] + s * (0.5 if star and k % 2 else 1) * math.cos(2 * math.pi * k / n),
                                          c[1] + s * (0.5 if star and k % 2 else 1) * math.sin(2 * math.pi * k / n),
                                          c[2]] for k in range(n)]})
        elif kind == 7:
            objects.append({"type": "polyhedron", "transform": move,
                            "planes": [[a, b, cc, -s] for a in (1, -1) for b in (1, -1) for cc in (1, -1)]})
        else:
            objects.append({"type": "quadric", "coefficients": [1, -1, 0, 0, 0, 0, 0, 0, -1 / s, 0],
                            "clip": {"min": [-s, -s, -s], "max": [s, s, s]}, "transform": move})
    for k in range(4):
        objects.append({"type": "patches", "file": os.path.normpath(TEAPOT),
                        "method": "analytic" if k % 2 == 0 else "subdivision",
                        "transform": [{"scale": 0.15}, {"rotate": {"axis": [1, 0, 0], "angle": rng.uniform(0, 360)}},
                                      {"translate": [rng.uniform(-4, 4) for _ in range(3)]}]})
    json.dump({"objects": objects}, sys.stdout)


if __name__ == "__main__":
    main()
