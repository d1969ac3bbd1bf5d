"""prism: a ray tracer for any OpenCL device, from Python.

    import prism
    image = prism.render("scene.json", width=64, height=48)   # float32 (48, 64, 4)

Scenes come from files (Scene.load), meshes (Scene.from_mesh), JSON or dicts
(Scene.from_json) or are built in code (Scene().add_sphere(...)); a Context on
a device renders them into NumPy arrays and answers ray queries on NumPy arrays
of rays. Errors are raised as prism.Error subclasses carrying prism's message.
docs/python.md has the tour."""

import os
import warnings

import numpy as np

from . import _capi
from ._capi import (Cancelled, DeviceError, Error, FileError, InvalidArgumentError, KernelBuildError, ParseError,
                    check, lib)
from .context import HIT_DTYPE, RAY_DTYPE, Context, Render, devices, rays
from .scene import Scene

__version__ = lib.prismGetVersionString().decode()

_default_contexts = {}


def _context(device):
    # One per device for the one-liners: a context compiles its kernels once.
    key = device if device is not None else ""
    if key not in _default_contexts:
        _default_contexts[key] = Context(device)
    return _default_contexts[key]


def render(scene, device=None, aovs=(), progress=None, **options):
    """Renders a scene (a Scene, a scene file's path, or a dict in the scene
    format) and returns its image, float32 (height, width, 4): linear RGB and
    coverage alpha. With `aovs`, returns the whole prism.Render instead. The
    device: `device`, else the scene's render.device, else the default. The
    render's warnings (stats["warnings"]: a device that failed mid-frame,
    pixels that are not finite) are issued as Python warnings, since the
    image alone carries no stats."""
    if not isinstance(scene, Scene):
        scene = Scene.from_json(scene) if isinstance(scene, dict) else Scene.load(scene)
    result = _context(device if device is not None else scene.device).render(scene, aovs=aovs, progress=progress,
                                                                             **options)
    if aovs:
        return result
    for message in result.stats["warnings"]:
        warnings.warn("prism: " + message, RuntimeWarning, stacklevel=2)
    return result.rgba


def write_image(path, pixels):
    """Writes (H, W), (H, W, 3) or (H, W, 4) float pixels, linear, to .png
    (8-bit sRGB), .exr, .hdr, .pfm or .tif."""
    p = np.ascontiguousarray(pixels, dtype=np.float32)
    channels = 1 if p.ndim == 2 else p.shape[2]
    check(lib.prismWriteImage(os.fsencode(path), p.ctypes.data, p.shape[1], p.shape[0], channels))


__all__ = ["Scene", "Context", "Render", "render", "devices", "rays", "write_image", "RAY_DTYPE", "HIT_DTYPE",
           "Error", "InvalidArgumentError", "FileError", "ParseError", "DeviceError", "KernelBuildError",
           "Cancelled"]
