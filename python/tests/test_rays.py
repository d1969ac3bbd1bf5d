"""Ray queries on NumPy arrays: hits against the closed form of a sphere and
a box, occlusion against the hits, and the zero-copy path for rays."""
import numpy as np
import pytest

import prism
from prism.context import _as_rays


@pytest.fixture(scope="module")
def sphere_scene():
    scene = prism.Scene()
    scene.add_sphere((0.5, -0.25, 0), 1.5)
    return scene


def random_rays(n, seed):
    rng = np.random.default_rng(seed)
    origins = rng.normal(size=(n, 3)) * 5
    targets = rng.uniform(-2, 2, size=(n, 3))
    return origins, targets - origins


@pytest.mark.parametrize("accel", ["none", "bvh", "octree", "bsp"])
def test_closest_hits_match_the_sphere_in_double_precision(ctx, sphere_scene, accel):
    origins, directions = random_rays(4000, 1)
    hits = ctx.intersect(sphere_scene, prism.rays(origins, directions), accel=accel)
    assert hits.dtype == prism.HIT_DTYPE and hits.shape == (4000,)
    o = origins.astype(np.float32).astype(np.float64) - (0.5, -0.25, 0)
    d = directions.astype(np.float32).astype(np.float64)
    a, b, c = (d * d).sum(1), (o * d).sum(1), (o * o).sum(1) - 2.25
    disc = b * b - a * c
    clear = np.abs(disc) > 1e-3 * a * 2.25  # leave out grazing rays
    inside = c < 0
    t = np.where(inside, (-b + np.sqrt(np.maximum(disc, 0))) / a, (-b - np.sqrt(np.maximum(disc, 0))) / a)
    expect_hit = (disc > 0) & (t > 0)
    assert ((hits["prim"] == 0) == expect_hit)[clear].all()
    sel = clear & expect_hit
    assert np.allclose(hits["t"][sel], t[sel], rtol=2e-5)
    assert np.isinf(hits["t"][clear & ~expect_hit]).all()


def test_occlusion_agrees_with_the_closest_hits(ctx, sphere_scene):
    origins, directions = random_rays(3000, 2)
    r = prism.rays(origins, directions, tmax=0.5)  # half-way to the target
    hits = ctx.intersect(sphere_scene, r)
    blocked = ctx.occluded(sphere_scene, r)
    assert blocked.dtype == bool
    assert (blocked == (hits["prim"] >= 0)).all()
    assert 0 < blocked.sum() < len(blocked)


def test_triangle_meshes_report_their_triangle_and_barycentrics(ctx):
    scene = prism.Scene()
    positions = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], dtype=np.float32)
    scene.add_mesh(positions, [[0, 1, 2], [1, 3, 2]])
    rng = np.random.default_rng(3)
    xy = rng.uniform(0.02, 0.98, size=(500, 2))
    xy = xy[np.abs(xy.sum(1) - 1) > 1e-3]  # off the shared edge
    origins = np.column_stack([xy, np.full(len(xy), 2.0)])
    hits = ctx.intersect(scene, prism.rays(origins, np.tile((0, 0, -1.0), (len(xy), 1))))
    assert np.allclose(hits["t"], 2.0, atol=1e-6)
    first = xy.sum(1) < 1
    assert (hits["prim"] == np.where(first, 0, 1)).all()
    # Triangle 0 = (0,0,0), (1,0,0), (0,1,0): u, v are the weights of vertices 1 and 2.
    assert np.allclose(hits["u"][first], xy[first, 0], atol=1e-5)
    assert np.allclose(hits["v"][first], xy[first, 1], atol=1e-5)


def test_contiguous_rays_are_passed_without_a_copy():
    flat = np.zeros((10, 8), dtype=np.float32)
    assert np.shares_memory(_as_rays(flat), flat)
    records = prism.rays(np.zeros((10, 3)), np.ones((10, 3)))
    assert np.shares_memory(_as_rays(records), records)
    strided = np.zeros((10, 16), dtype=np.float32)[:, ::2]
    assert not np.shares_memory(_as_rays(strided), strided)  # copied, and still right
    assert _as_rays(np.zeros((4, 8))).dtype == prism.RAY_DTYPE  # float64 converted
    with pytest.raises(prism.InvalidArgumentError, match=r"\(N, 8\)"):
        _as_rays(np.zeros((4, 7), dtype=np.float32))
