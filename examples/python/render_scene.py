"""A scene built in Python and rendered into a NumPy array: a checkered floor, a
glass sphere and a pyramid from arrays, then written as a PNG. The C version is
examples/c/render_scene.c.

    python render_scene.py [OUT.png] [--check]
"""
import sys

import numpy as np

import prism

scene = prism.Scene()
scene.set_background((0.5, 0.7, 1.0))
scene.add_material("floor", checker=((1, 1, 1), (0, 0, 0), 0.5))
scene.add_material("glass", diffuse=0.02, specular=0.9, shininess=200, reflect=0.1, transmit=0.9, ior=1.5)
scene.add_plane(point=(0, 0, 0), normal=(0, 1, 0), material="floor")
scene.add_sphere(center=(1.2, 0.6, 1.2), radius=0.6, material="glass")
scene.add_mesh([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1], [0, 1.5, 0]],
               [[0, 4, 1], [1, 4, 2], [2, 4, 3], [3, 4, 0]])
scene.add_point_light(position=(3, 5, 4))
scene.camera = {"position": (2.5, 2.5, 5.0), "look_at": (0, 0.5, 0)}

result = prism.Context("cpu").render(scene, width=160, height=120, aovs=("depth",))
out = next((a for a in sys.argv[1:] if not a.startswith("--")), None)
if out:
    prism.write_image(out, result.rgba)
covered = result.rgba[..., 3].mean()
print("%dx%d, %.0f%% of pixels covered, nearest hit %.3f, %d rays in %.3f s"
      % (result.rgba.shape[1], result.rgba.shape[0], 100 * covered, np.min(result.aovs["depth"]),
         sum(result.stats[k] for k in ("primary_rays", "reflected_rays", "refracted_rays", "shadow_rays")),
         result.stats["seconds"]))
if "--check" in sys.argv and not 0.5 < covered < 1:
    sys.exit(1)
