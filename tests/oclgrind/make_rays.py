"""Writes N rays for `prism trace` (32-byte records: origin, tmin, direction,
tmax) from a ring around the origin towards points near it, so that some hit
the Whitted scene's spheres and plane and some miss."""
import math
import struct
import sys

path, n = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 64
with open(path, "wb") as f:
    for i in range(n):
        a = 2 * math.pi * i / n
        o = (6 * math.cos(a), 1.5 + math.sin(3 * a), 6 * math.sin(a))
        target = (0.5 * math.sin(5 * a), 0.8, 0.5 * math.cos(7 * a))
        d = tuple(t - s for s, t in zip(o, target))
        f.write(struct.pack("<8f", *o, 0.0, *d, 1e30 if i % 3 else 0.9))
