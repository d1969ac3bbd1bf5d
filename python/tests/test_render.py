"""Rendering from Python: the one-liner's contract, scenes built in code
against the same scenes as text, AOVs against the camera's closed form,
progress and cancellation, errors carrying prism's messages."""
import math
import os
import warnings

import numpy as np
import pytest

import prism


def test_one_liner_returns_linear_rgba_of_the_asked_size(scenes_dir):
    image = prism.render(os.path.join(scenes_dir, "whitted.json"), width=64, height=48, device="cpu")
    assert image.shape == (48, 64, 4) and image.dtype == np.float32
    assert np.isfinite(image).all()
    alpha = image[..., 3]
    assert set(np.unique(alpha)) <= {0.0, 1.0}  # coverage of one sample per pixel
    assert 0 < alpha.mean() < 1  # the plane below, the sky above


def whitted_dict():
    return {
        "camera": {"position": [0, 2.0, 6.5], "look_at": [0, 0.8, 0], "fov": 40},
        "render": {"ambient": [0.15, 0.15, 0.15], "background": [0.5, 0.5, 0.75]},
        "materials": {
            "checker": {"diffuse": [0.9, 0.9, 0.9], "shininess": 16,
                        "texture": {"type": "checker", "color1": [1, 0, 0], "color2": [1, 1, 0], "scale": 1}},
            "glass": {"model": "blinn", "ambient": 0, "diffuse": 0.0625, "specular": 0.875, "shininess": 300,
                      "reflect": 0.125, "transmit": 0.875, "ior": 1.5},
            "brushed": {"model": "cook-torrance", "roughness": 0.25, "distribution": "ggx", "specular": 0.75},
        },
        "lights": [{"position": [-4, 7, 6], "intensity": 0.75}],
        "objects": [
            {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "checker"},
            {"type": "sphere", "center": [-0.75, 1, 0.75], "radius": 1, "material": "glass"},
            {"type": "box", "min": [1, 0, -1], "max": [2, 1, 0], "material": "brushed"},
            {"type": "triangle", "vertices": [[-3, 0, -2], [-1, 0, -2], [-2, 2, -2]], "material": "glass"},
            # (x - 2.5)^2 + (z - 1)^2 = 0.25, 0 <= y <= 1.5: a capped cylinder as a general quadric
            {"type": "quadric", "coefficients": [1, 0, 1, 0, 0, 0, -5, 0, -2, 7],
             "clip": {"min": [2, 0, 0.5], "max": [3, 1.5, 1.5]}, "capped": True, "material": "brushed"},
            {"type": "polygon", "vertices": [[-3, 0.5, 1.5], [-2, 0.5, 1.5], [-2, 1.5, 1.5], [-2.5, 1, 1.5],
                                             [-3, 1.5, 1.5]], "inside_test": "radial", "material": "glass"},
            {"type": "polyhedron", "planes": [[1, 1, 1, -0.5], [1, -1, -1, -0.5], [-1, 1, -1, -0.5], [-1, -1, 1, -0.5]],
             "transform": {"matrix": [1, 0, 0, 0.5, 0, 1, 0, 0.5, 0, 0, 1, 2, 0, 0, 0, 1]}, "material": "brushed"},
        ],
    }


def test_a_scene_built_in_code_renders_as_the_same_scene_as_json(ctx):
    # Every number is a float exactly, so both routes hold the same values.
    built = prism.Scene()
    built.camera = {"position": (0, 2.0, 6.5), "look_at": (0, 0.8, 0), "fov": 40}
    built.set_ambient(0.15).set_background((0.5, 0.5, 0.75))
    built.add_material("checker", diffuse=0.9, shininess=16, checker=((1, 0, 0), (1, 1, 0), 1))
    built.add_material("glass", model="blinn", ambient=0, diffuse=0.0625, specular=0.875, shininess=300,
                       reflect=0.125, transmit=0.875, ior=1.5)
    built.add_material("brushed", model="cook-torrance", roughness=0.25, distribution="ggx", specular=0.75)
    built.add_point_light((-4, 7, 6), intensity=0.75)
    assert built.add_plane((0, 0, 0), (0, 1, 0), material="checker") == 0
    assert built.add_sphere((-0.75, 1, 0.75), 1, material="glass") == 1
    assert built.add_box((1, 0, -1), (2, 1, 0), material="brushed") == 2
    assert built.add_triangle([[-3, 0, -2], [-1, 0, -2], [-2, 2, -2]], material="glass") == 3
    assert built.add_quadric([1, 0, 1, 0, 0, 0, -5, 0, -2, 7], (2, 0, 0.5), (3, 1.5, 1.5), capped=True,
                             material="brushed") == 4
    assert built.add_polygon([[-3, 0.5, 1.5], [-2, 0.5, 1.5], [-2, 1.5, 1.5], [-2.5, 1, 1.5], [-3, 1.5, 1.5]],
                             inside_test="radial", material="glass") == 5
    assert built.add_polyhedron([[1, 1, 1, -0.5], [1, -1, -1, -0.5], [-1, 1, -1, -0.5], [-1, -1, 1, -0.5]],
                                material="brushed",
                                transform=[[1, 0, 0, 0.5], [0, 1, 0, 0.5], [0, 0, 1, 2], [0, 0, 0, 1]]) == 6
    assert built.object_count == 7
    written = prism.Scene.from_json(whitted_dict())
    a = ctx.render(built, width=72, height=40, max_depth=6, aovs=("depth", "primid"))
    b = ctx.render(written, width=72, height=40, max_depth=6, aovs=("depth", "primid"))
    assert a.rgba.tobytes() == b.rgba.tobytes()
    assert a.aovs["depth"].tobytes() == b.aovs["depth"].tobytes()
    assert (a.aovs["primid"] == b.aovs["primid"]).all()
    assert set(np.unique(a.aovs["primid"])) == {-1, 0, 1, 2, 3, 4, 5, 6}  # every object is seen, and the sky


def test_depth_and_primid_match_the_cameras_closed_form(ctx):
    # A sphere of radius 1 at the origin seen from z = 4: the primary ray through
    # pixel (i, j)'s centre is known, and so is where it meets the sphere.
    width, height, fov = 40, 30, 50.0
    scene = prism.Scene()
    scene.camera = {"position": (0, 0, 4), "look_at": (0, 0, 0), "fov": fov}
    scene.add_sphere((0, 0, 0), 1)
    r = ctx.render(scene, width=width, height=height, aovs=("depth", "primid", "normal"))
    depth, primid, normal = r.aovs["depth"], r.aovs["primid"], r.aovs["normal"]
    assert depth.shape == (height, width) and normal.shape == (height, width, 3) and primid.dtype == np.int32
    tan_half = math.tan(math.radians(fov) / 2)
    compared = 0
    for j in range(height):
        for i in range(width):
            x = (2 * (i + 0.5) / width - 1) * tan_half * width / height
            y = (1 - 2 * (j + 0.5) / height) * tan_half
            d = np.array([x, y, -1.0]) / math.sqrt(x * x + y * y + 1)
            o = np.array([0, 0, 4.0])
            b = o @ d
            disc = b * b - (o @ o - 1)
            if abs(disc) < 1e-3:  # grazing: either answer is right in float
                continue
            compared += 1
            if disc < 0:
                assert primid[j, i] == -1 and math.isinf(depth[j, i])
            else:
                t = -b - math.sqrt(disc)
                assert primid[j, i] == 0
                assert depth[j, i] == pytest.approx(t, rel=1e-5)
                assert normal[j, i] == pytest.approx((o + t * d), abs=1e-4)  # the unit sphere's normal is the point
    assert compared > 0.95 * width * height


def test_progress_is_reported_and_can_cancel(ctx, scenes_dir):
    scene = prism.Scene.load(os.path.join(scenes_dir, "whitted.json"))
    seen = []
    ctx.render(scene, width=32, height=24, progress=lambda f: seen.append(f))
    assert seen and all(0 <= f <= 1 for f in seen) and seen == sorted(seen)
    with pytest.raises(prism.Cancelled, match="cancel"):
        ctx.render(scene, width=32, height=24, progress=lambda f: True)

    def broken(f):
        raise KeyError("from the callback")

    with pytest.raises(KeyError, match="from the callback"):
        ctx.render(scene, width=32, height=24, progress=broken)
    ctx.render(scene, width=8, height=6)  # the context still renders afterwards


def test_errors_are_exceptions_with_prisms_messages(ctx, tmp_path):
    bad = {"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": -1}]}
    with pytest.raises(prism.ParseError) as from_json:
        prism.Scene.from_json(bad, name="bad")
    assert "bad: objects[0].radius: expected a positive number, got -1" in str(from_json.value)
    with pytest.raises(prism.InvalidArgumentError) as from_call:
        prism.Scene().add_sphere((0, 0, 0), -1)
    assert str(from_call.value).endswith(str(from_json.value).split("bad: ", 1)[1])  # the same words
    with pytest.raises(prism.FileError, match="no-such-file.json"):
        prism.Scene.load(str(tmp_path / "no-such-file.json"))
    with pytest.raises(prism.InvalidArgumentError, match="width"):
        ctx.render(prism.Scene(), width=0, height=10)
    with pytest.raises(prism.InvalidArgumentError, match="unknown"):
        ctx.render(prism.Scene(), width=8, height=8, accel="kd-tree")
    with pytest.raises(prism.DeviceError):
        prism.Context("no-such-device")
    assert isinstance(from_call.value, ValueError) and isinstance(from_call.value, prism.Error)


def test_devices_and_images(ctx, tmp_path):
    listed = prism.devices()
    assert listed and ctx.device["name"] in [d["name"] for d in listed]
    assert ctx.device["type"] == "cpu"
    image = np.zeros((6, 8, 4), dtype=np.float32)
    image[..., 0] = np.linspace(0, 1, 8)
    prism.write_image(str(tmp_path / "ramp.pfm"), image)
    assert (tmp_path / "ramp.pfm").stat().st_size > 6 * 8 * 3 * 4


def test_the_inside_tests_render_alike_and_left_right_refuses_a_non_convex_polygon(ctx):
    scene = prism.Scene.from_json(whitted_dict())
    # A non-convex polygon that names no test of its own (the other one names radial).
    scene.add_polygon([[0, 2, -1], [1, 2, -1], [1, 3, -1], [0.5, 2.5, -1], [0, 3, -1]])
    crossing = ctx.render(scene, width=48, height=32, inside_test="crossing")
    radial = ctx.render(scene, width=48, height=32, inside_test="radial")
    assert crossing.rgba.tobytes() == radial.rgba.tobytes()
    with pytest.raises(prism.InvalidArgumentError, match="left-right' needs a convex polygon"):
        ctx.render(scene, width=48, height=32, inside_test="left-right")


def read_bpt(path):
    """The control points of a .bpt file as an (N, 16, 3) array, read here independently of prism."""
    with open(path) as f:
        words = f.read().split()
    count, at, patches = int(words[0]), 1, []
    for _ in range(count):
        assert words[at:at + 2] == ["3", "3"]
        patches.append(np.array(words[at + 2:at + 2 + 48], dtype=np.float64).reshape(16, 3))
        at += 50
    return np.array(patches)


def test_patches_given_as_arrays_render_as_the_same_file_and_both_methods_agree(ctx, scenes_dir):
    bpt = os.path.join(scenes_dir, "patches", "teapot.bpt")
    points = read_bpt(bpt)
    assert points.shape == (32, 16, 3)
    stand = [[1, 0, 0, 0], [0, 0, 1, 0], [0, -1, 0, 0], [0, 0, 0, 1]]  # z up in the file -> y up
    images = {}
    for name, kwargs in {"arrays": {"control_points": points}, "file": {"file": bpt},
                         "analytic": {"control_points": points, "method": "analytic"}}.items():
        scene = prism.Scene()
        scene.camera = {"position": (0, 3, 9), "look_at": (0, 1.2, 0), "fov": 40}
        index = scene.add_patches(transform=stand, **kwargs)
        assert index == 0 and scene.object_count == 1
        images[name] = ctx.render(scene, width=64, height=48, aovs=("depth", "primid"))
    a, f, n = images["arrays"], images["file"], images["analytic"]
    assert a.rgba.tobytes() == f.rgba.tobytes()
    assert a.aovs["depth"].tobytes() == f.aovs["depth"].tobytes()
    hit = (a.aovs["primid"] >= 0) & (n.aovs["primid"] >= 0)
    assert hit.sum() > 64 * 48 / 8
    # The triangles lie within the default tolerance (a thousandth of the size,
    # about 0.0066) of the surface: the depths agree to a few tolerances.
    assert np.median(np.abs(a.aovs["depth"][hit] - n.aovs["depth"][hit])) < 0.02
    with pytest.raises(ValueError):
        prism.Scene().add_patches()
    with pytest.raises(prism.Error, match="16 control points"):
        prism.Scene().add_patches(control_points=np.zeros((1, 15, 3)))


def test_the_light_buffer_casts_the_structures_shadows(ctx, scenes_dir):
    scene = prism.Scene.load(os.path.join(scenes_dir, "whitted.json"))
    a = ctx.render(scene, width=64, height=48, shadows="accel")
    b = ctx.render(scene, width=64, height=48, shadows="lightbuffer")
    assert a.stats["shadows"] == "accel" and b.stats["shadows"] == "lightbuffer"
    assert np.abs(a.rgba - b.rgba).max() <= 1e-6
    with pytest.raises(prism.Error, match="unknown shadow mode"):
        ctx.render(scene, shadows="shadowmap")


def test_kdop_bounds_render_the_boxes_image(ctx, scenes_dir):
    scene = prism.Scene.load(os.path.join(scenes_dir, "teapot.json"))
    a = ctx.render(scene, width=64, height=48, bounds="aabb", accel="bvh")
    b = ctx.render(scene, width=64, height=48, bounds="kdop", accel="bvh")
    assert np.array_equal(a.rgba, b.rgba)
    with pytest.raises(prism.Error, match="unknown bounds"):
        ctx.render(scene, bounds="obb")


def test_check_nan_reports_none_on_a_plain_scene(ctx, scenes_dir):
    scene = prism.Scene.load(os.path.join(scenes_dir, "whitted.json"))
    r = ctx.render(scene, width=32, height=24, check_nan=True)
    assert np.isfinite(r.rgba).all()
    assert r.stats["nan"] is None
    assert "nan" not in ctx.render(scene, width=32, height=24).stats


_SEVERAL_DEVICES = r"""
import sys, numpy as np, prism
scene = prism.Scene.load(sys.argv[1])
one = prism.Context("0")
several = prism.Context("all")
assert len(several.devices) == 3 and len(one.devices) == 1, several.devices
a = one.render(scene, width=320, height=240, aa="jitter", spp=4, aovs=("depth", "primid"))
b = several.render(scene, width=320, height=240, aa="jitter", spp=4, aovs=("depth", "primid"))
assert a.rgba.tobytes() == b.rgba.tobytes()
assert a.aovs["depth"].tobytes() == b.aovs["depth"].tobytes()
assert (a.aovs["primid"] == b.aovs["primid"]).all()
shares = b.stats["devices"]
assert [s["device"] for s in shares] == [d["name"] for d in several.devices]
assert sum(s["samples"] for s in shares) == 320 * 240 * 4 and not any(s["failed"] for s in shares)
# The first device resolves the frame and holds its film (rgba and x, y: 24 bytes a
# sample); the others one unit of 65,536 samples each.
assert [s["film_bytes"] for s in shares] == [24 * 320 * 240 * 4] + [24 * 65536] * 2, shares
assert b.stats["warnings"] == [] and len(a.stats["devices"]) == 1
print("ok")
"""


def test_the_one_liner_warns_of_pixels_that_are_not_finite(scenes_dir):
    # A diffuse colour of 1e6 on a checker of 1e6 under a light of 1e30: each
    # within its bound, 1e42 together, past float at every lit point.
    bright = {
        "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40},
        "materials": {"hot": {"diffuse": 1e6, "texture": {"type": "checker", "color1": 1e6, "color2": 1e6}}},
        "lights": [{"position": [0, 0, 5], "intensity": 1e30}],
        "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "hot"}],
    }
    with pytest.warns(RuntimeWarning, match="pixels are not finite") as caught:
        image = prism.render(bright, width=16, height=16, device="cpu")
    bad = int((~np.isfinite(image).all(axis=2)).sum())
    assert bad > 0
    assert any(str(w.message).startswith("prism: %d of the colour image's 256 pixels" % bad) for w in caught)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a plain scene warns of nothing
        prism.render(os.path.join(scenes_dir, "whitted.json"), width=16, height=12, device="cpu")


def test_a_frame_over_several_devices_is_the_image_of_one(scenes_dir):
    # Three PoCL devices of one kind, which the OpenCL platform reads at start-up:
    # so in a process of its own.
    import subprocess
    import sys
    env = dict(os.environ, POCL_DEVICES="pthread pthread pthread")
    done = subprocess.run([sys.executable, "-c", _SEVERAL_DEVICES, os.path.join(scenes_dir, "whitted.json")],
                          env=env, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0 and done.stdout.strip() == "ok", done.stdout + done.stderr


def test_the_one_liner_renders_on_the_scene_s_devices_unless_told_otherwise():
    # The scene's render.device is honoured: a selector naming no device fails
    # with prism's message, and an explicit device overrides it.
    scene = whitted_dict()
    scene.setdefault("render", {})["device"] = "no-such-device-xyz"
    assert prism.Scene.from_json(scene).device == "no-such-device-xyz"
    assert prism.Scene.from_json(whitted_dict()).device is None
    with pytest.raises(prism.DeviceError, match="no-such-device-xyz"):
        prism.render(scene, width=8, height=6)
    image = prism.render(scene, device="0", width=8, height=6)
    assert image.shape == (6, 8, 4)


def test_animation_frames_render_as_the_scenes_written_for_them(ctx):
    # A sphere from x = -2 to x = 2 over 5 still frames: frame k is the scene
    # with the sphere at -2 + k, bit for bit (values exact in binary).
    def scene(x0, x1=None, frames=None):
        sphere = {"type": "sphere", "center": [0, 0, 0], "radius": 0.75, "transform": {"translate": [x0, 0, 0]}}
        if x1 is not None:
            sphere["transform_end"] = {"translate": [x1, 0, 0]}
        d = {"camera": {"position": [0, 0, 8], "look_at": [0, 0, 0]}, "film": {"width": 32, "height": 24},
             "lights": [{"position": [3, 5, 6]}], "objects": [sphere]}
        if frames:
            d["animation"] = {"frames": frames}
        return prism.Scene.from_json(d)

    animated = scene(-2, 2, frames=5)
    assert animated.frame_count == 5 and scene(0).frame_count == 1
    for k in (0, 3):
        frame = animated.frame(k)
        assert frame.frame_count == 1
        assert np.array_equal(ctx.render(frame).rgba, ctx.render(scene(-2 + k)).rgba)
    assert np.array_equal(ctx.render(animated.frame(np.int64(4))).rgba, ctx.render(scene(2)).rgba)
    for bad in (5, -1, 2**40):
        with pytest.raises(ValueError, match="the scene has frames 0 to 4"):
            animated.frame(bad)
    with pytest.raises(TypeError):
        animated.frame(1.0)
