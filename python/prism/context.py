"""prism.Context: one OpenCL device, rendering scenes into NumPy arrays and
answering ray queries on NumPy arrays of rays."""

import ctypes
import math

import numpy as np

from . import _capi
from ._capi import check, lib

# The C API's records (include/prism.h): PrismRay is 32 bytes, PrismHit 16.
RAY_DTYPE = np.dtype([("org", np.float32, 3), ("tmin", np.float32), ("dir", np.float32, 3), ("tmax", np.float32)])
HIT_DTYPE = np.dtype([("t", np.float32), ("prim", np.int32), ("u", np.float32), ("v", np.float32)])
assert RAY_DTYPE.itemsize == 32 and HIT_DTYPE.itemsize == 16

_ENUM_OPTIONS = {"accel": lib.prismParseAccel, "aa": lib.prismParseAa, "filter": lib.prismParseFilter,
                 "first_hit": lib.prismParseFirstHit, "inside_test": lib.prismParseInsideTest,
                 "shadows": lib.prismParseShadows, "bounds": lib.prismParseBounds}
_PLAIN_OPTIONS = ("width", "height", "spp", "max_depth", "min_weight", "seed", "aa_threshold", "aa_max_level",
                  "check_nan")


def devices():
    """The OpenCL devices prism can use, as dicts (index, name, vendor, platform,
    type, compute_units, global_memory_bytes)."""
    count = ctypes.c_uint32()
    check(lib.prismGetDeviceCount(ctypes.byref(count)))
    return [_device_dict(_device_info(i)) for i in range(count.value)]


def _device_info(index):
    info = _capi.DeviceInfo()
    check(lib.prismGetDeviceInfo(index, ctypes.byref(info)))
    return info


def _device_dict(info):
    kinds = {1: "cpu", 2: "gpu", 4: "accelerator"}
    return {"index": info.index, "name": info.name.decode(), "vendor": info.vendor.decode(),
            "platform": info.platform.decode(), "driver_version": info.driver_version.decode(),
            "type": kinds.get(info.type, "other"), "compute_units": info.compute_units,
            "global_memory_bytes": info.global_memory_bytes}


def rays(origins, directions, tmin=0.0, tmax=math.inf):
    """An array of rays (RAY_DTYPE) from (N, 3) origins and directions; tmin and
    tmax are scalars or (N,) arrays. Directions need not be unit length."""
    o = np.asarray(origins, dtype=np.float32).reshape(-1, 3)
    d = np.asarray(directions, dtype=np.float32).reshape(-1, 3)
    out = np.empty(max(len(o), len(d)), dtype=RAY_DTYPE)
    out["org"], out["dir"], out["tmin"], out["tmax"] = o, d, tmin, tmax
    return out


def _as_rays(array):
    """The rays as a contiguous RAY_DTYPE array: the caller's own memory when it
    already is one (or an (N, 8) float32 C-contiguous array), else a copy."""
    a = np.asarray(array)
    if a.dtype == RAY_DTYPE and a.flags.c_contiguous:
        return a.reshape(-1)
    if a.dtype == np.float32 and a.ndim == 2 and a.shape[1] == 8 and a.flags.c_contiguous:
        return a.view(RAY_DTYPE).reshape(-1)
    if a.dtype.names is None and a.ndim == 2 and a.shape[1] == 8:
        return np.ascontiguousarray(a, dtype=np.float32).view(RAY_DTYPE).reshape(-1)
    if a.dtype.names is not None:
        return np.ascontiguousarray(a.astype(RAY_DTYPE)).reshape(-1)
    raise _capi.InvalidArgumentError("rays: expected an (N, 8) float array (org xyz, tmin, dir xyz, tmax) or an "
                                     "array of prism.RAY_DTYPE, got shape %s of %s" % (a.shape, a.dtype),
                                     "PRISM_ERROR_INVALID_ARGUMENT")


class Render:
    """One render's results: `rgba` (H, W, 4 float32: linear RGB and coverage
    alpha), `aovs` (name -> array: depth (H, W), normal (H, W, 3), primid
    (H, W) int32, albedo (H, W, 3)) and `stats` (a dict)."""

    def __init__(self, rgba, aovs, stats):
        self.rgba, self.aovs, self.stats = rgba, aovs, stats


class Context:
    """A context on one device: None or "" for the default (the first GPU, else
    the first device), an index, "cpu", "gpu", or part of the device's name; or
    on several, which share each frame (the same image bit for bit): "all", or a
    comma-separated list of those ("0,2")."""

    def __init__(self, device=None):
        handle = ctypes.c_void_p()
        check(lib.prismCreateContext(device.encode() if isinstance(device, str) else
                                     (str(device).encode() if device is not None else None), None,
                                     ctypes.byref(handle)))
        self._handle = handle

    def __del__(self):
        handle, self._handle = getattr(self, "_handle", None), None
        if handle:
            lib.prismReleaseContext(handle)

    @property
    def device(self):
        """The (first) device, as a dict like those of prism.devices()."""
        info = _capi.DeviceInfo()
        check(lib.prismGetContextDevice(self._handle, ctypes.byref(info)))
        return _device_dict(info)

    @property
    def devices(self):
        """Every device the context shares its frames over, first first."""
        count = ctypes.c_uint32()
        check(lib.prismGetContextDeviceCount(self._handle, ctypes.byref(count)))
        out = []
        for i in range(count.value):
            info = _capi.DeviceInfo()
            check(lib.prismGetContextDeviceAt(self._handle, i, ctypes.byref(info)))
            out.append(_device_dict(info))
        return out

    def options(self, scene, **overrides):
        """The scene's render options with `overrides` applied and checked."""
        o = _capi.RenderOptions()
        o.struct_size = ctypes.sizeof(o)
        check(lib.prismGetRenderOptions(scene._handle, ctypes.byref(o)))
        for key, value in overrides.items():
            if key in _ENUM_OPTIONS:
                setattr(o, key, _capi.enum_value(_ENUM_OPTIONS[key], value, key))
            elif key in _PLAIN_OPTIONS:
                setattr(o, key, value)
            else:
                raise TypeError("render() got an unexpected option %r (known: %s)"
                                % (key, ", ".join(sorted(_PLAIN_OPTIONS + tuple(_ENUM_OPTIONS)))))
        check(lib.prismCheckRenderOptions(ctypes.byref(o)))
        return o

    def render(self, scene, aovs=(), progress=None, **options):
        """Renders `scene`; returns a Render. `options`: width, height, spp,
        max_depth, min_weight, seed, accel, aa, filter, first_hit, inside_test,
        shadows, bounds, aa_threshold, aa_max_level (the scene's own where not given), check_nan (True: the
        stats' "nan" is None or the first non-finite contribution and its ray). `aovs`: names among depth,
        normal, primid, albedo. The stats' "devices" say how much of the frame each
        device traced and the film memory it held ("film_bytes": the whole frame's on
        the device that resolves it, one unit's on the others), "warnings" name a device that failed mid-frame (the others
        traced its part) and count the image's pixels that are not finite. `progress(fraction)` is called as the render goes;
        return True from it to cancel (prism.Cancelled is raised)."""
        o = self.options(scene, **options)
        rgba = np.empty((o.height, o.width, 4), dtype=np.float32)
        stats = _capi.RenderStats()
        stats.struct_size = ctypes.sizeof(stats)
        raised = []

        def report(_user, fraction):
            try:
                return 1 if progress(fraction) else 0
            except BaseException as e:  # an exception cannot cross C: cancel, and raise it afterwards
                raised.append(e)
                return 1

        callback = _capi.ProgressFn(report) if progress else _capi.ProgressFn()
        check(lib.prismSetProgressCallback(self._handle, callback, None))
        try:
            status = lib.prismRender(self._handle, scene._handle, ctypes.byref(o), rgba.ctypes.data,
                                     ctypes.byref(stats))
        finally:
            lib.prismSetProgressCallback(self._handle, _capi.ProgressFn(), None)
        if raised:
            raise raised[0]
        check(status)
        stats_dict = _stats_dict(stats)
        stats_dict["devices"] = self._device_shares()
        stats_dict["warnings"] = self._warnings()
        if o.check_nan:
            stats_dict["nan"] = self._nan_report()
        return Render(rgba, {name: self._aov(name, o) for name in aovs}, stats_dict)

    def _device_shares(self):
        count = ctypes.c_uint32()
        check(lib.prismGetRenderDeviceShareCount(self._handle, ctypes.byref(count)))
        shares = []
        for i in range(count.value):
            share = _capi.DeviceShare()
            share.struct_size = ctypes.sizeof(share)
            check(lib.prismGetRenderDeviceShare(self._handle, i, ctypes.byref(share)))
            shares.append({"device": (share.device or b"").decode(), "units": share.units, "samples": share.samples,
                           "busy_seconds": share.busy_seconds, "failed": bool(share.failed),
                           "failure": (share.failure or b"").decode(), "film_bytes": share.film_bytes})
        return shares

    def _warnings(self):
        count = ctypes.c_uint32()
        check(lib.prismGetRenderWarningCount(self._handle, ctypes.byref(count)))
        out = []
        for i in range(count.value):
            text = ctypes.c_char_p()
            check(lib.prismGetRenderWarning(self._handle, i, ctypes.byref(text)))
            out.append(text.value.decode())
        return out

    def _nan_report(self):
        r = _capi.NanReport()
        r.struct_size = ctypes.sizeof(r)
        check(lib.prismGetNanReport(self._handle, ctypes.byref(r)))
        if not r.found:
            return None
        kinds = ("primary", "reflected", "refracted", "shadow")
        return {"sample": r.sample, "film": (r.film_x, r.film_y),
                "ray_kind": kinds[r.ray_kind] if r.ray_kind < 4 else "?", "ray_depth": r.ray_depth,
                "origin": tuple(r.origin), "direction": tuple(r.direction), "primitive": r.primitive, "t": r.t,
                "value": tuple(r.value)}

    def _aov(self, name, o):
        which = _capi.enum_value(lib.prismParseAov, name, "aov")
        channels = ctypes.c_uint32()
        check(lib.prismGetAovChannels(which, ctypes.byref(channels)))
        shape = (o.height, o.width) if channels.value == 1 else (o.height, o.width, channels.value)
        out = np.empty(shape, dtype=np.float32)
        check(lib.prismGetAov(self._handle, which, out.ctypes.data, out.size))
        return out.astype(np.int32) if name == "primid" else out

    def intersect(self, scene, rays, accel="auto"):
        """Closest hits of `rays` (see prism.rays) as an array of HIT_DTYPE
        (t: +inf and prim: -1 on a miss; u, v: barycentrics on triangles)."""
        r = _as_rays(rays)
        hits = np.empty(r.shape[0], dtype=HIT_DTYPE)
        check(lib.prismIntersect(self._handle, scene._handle, _capi.enum_value(lib.prismParseAccel, accel, "accel"),
                                 r.ctypes.data, hits.ctypes.data, r.shape[0], None))
        return hits

    def occluded(self, scene, rays, accel="auto"):
        """Whether anything lies in (tmin, tmax) along each ray: a bool array."""
        r = _as_rays(rays)
        out = np.empty(r.shape[0], dtype=np.uint8)
        check(lib.prismOccluded(self._handle, scene._handle, _capi.enum_value(lib.prismParseAccel, accel, "accel"),
                                r.ctypes.data, out.ctypes.data, r.shape[0], None))
        return out.astype(bool)


def _stats_dict(s):
    return {"seconds": s.seconds, "setup_seconds": s.setup_seconds, "trace_seconds": s.trace_seconds,
            "first_launch_seconds": s.first_launch_seconds,
            "kernel_build_seconds": s.kernel_build_seconds, "primary_rays": s.primary_rays,
            "reflected_rays": s.reflected_rays, "refracted_rays": s.refracted_rays, "shadow_rays": s.shadow_rays,
            "rays_per_depth": [s.rays_per_depth[i] for i in range(min(s.waves, 32))],
            "shadows": (lib.prismShadowsName(s.shadows_used) or b"?").decode()}
