"""prism as a ray-query engine from Python: a cube from NumPy arrays, a grid of
rays shot straight down at it, every hit checked against the closed form (the
top face at t = 4 inside the square, a miss outside). The C version is
examples/c/query_mesh.c.

    python query_mesh.py [--check]
"""
import sys

import numpy as np

import prism

corners = np.array([[x, y, z] for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)], dtype=np.float32)
faces = np.array([[0, 3, 1], [0, 2, 3], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4],
                  [2, 6, 7], [2, 7, 3], [1, 3, 7], [1, 7, 5], [0, 4, 6], [0, 6, 2]])
scene = prism.Scene()
scene.add_mesh(corners, faces)

n = 64
xy = (np.stack(np.meshgrid(np.arange(n), np.arange(n)), -1).reshape(-1, 2) + 0.5) / n * 4 - 2
origins = np.column_stack([xy, np.full(len(xy), 5.0)])
hits = prism.Context("cpu").intersect(scene, prism.rays(origins, np.tile((0, 0, -1.0), (len(xy), 1))))

inside = (np.abs(xy) < 1).all(axis=1)
wrong = ((hits["prim"] >= 0) != inside) | (inside & (np.abs(hits["t"] - 4) > 1e-5))
print("%d rays, %d hits, %d disagree with the closed form" % (len(xy), (hits["prim"] >= 0).sum(), wrong.sum()))
if "--check" in sys.argv and wrong.any():
    sys.exit(1)
