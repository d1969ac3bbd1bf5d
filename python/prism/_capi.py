"""ctypes declarations of prism's C API (include/prism.h): the library the
package ships (lib/libprism.so beside this file), its structs and functions,
and the exception each status becomes. Nothing here is public."""

import ctypes
import os
from ctypes import (CFUNCTYPE, POINTER, Structure, c_char, c_char_p, c_double, c_float, c_int, c_int32, c_size_t,
                    c_uint32, c_uint64, c_void_p)


def _library_path():
    # PRISM_LIBRARY: a build tree's libprism.so, for developing prism itself.
    override = os.environ.get("PRISM_LIBRARY")
    if override:
        return override
    # `pip install .` puts the library (by its soname) in lib/ beside this file.
    here = os.path.dirname(os.path.abspath(__file__))
    for name in ("libprism.so.0", "libprism.so"):
        path = os.path.join(here, "lib", name)
        if os.path.exists(path):
            return path
    raise ImportError("prism: libprism.so is not in %s/lib; install the package with `pip install .` from "
                      "prism's source tree, or point PRISM_LIBRARY at a built libprism.so" % here)


lib = ctypes.CDLL(_library_path())

Status = c_int
float3 = c_float * 3


class DeviceInfo(Structure):
    _fields_ = [("index", c_uint32), ("name", c_char * 256), ("vendor", c_char * 256), ("platform", c_char * 256),
                ("driver_version", c_char * 128), ("opencl_c_version", c_char * 128), ("type", c_int),
                ("compute_units", c_uint32), ("global_memory_bytes", c_uint64)]


class Camera(Structure):
    _fields_ = [("struct_size", c_size_t), ("position", float3), ("look_at", float3), ("up", float3),
                ("fov_degrees", c_float), ("aperture", c_float), ("focus_distance", c_float),
                ("shutter_open", c_float), ("shutter_close", c_float), ("moving", c_int),
                ("position_end", float3), ("look_at_end", float3)]


class RenderOptions(Structure):
    _fields_ = [("struct_size", c_size_t), ("width", c_uint32), ("height", c_uint32), ("spp", c_uint32),
                ("max_depth", c_uint32), ("min_weight", c_float), ("seed", c_uint64), ("accel", c_uint32),
                ("aa", c_uint32), ("filter", c_uint32), ("first_hit", c_uint32), ("aa_threshold", c_float),
                ("aa_max_level", c_uint32), ("profile", c_uint32), ("inside_test", c_uint32), ("shadows", c_uint32),
                ("bounds", c_uint32), ("check_nan", c_uint32)]


class NanReport(Structure):
    _fields_ = [("struct_size", c_size_t), ("found", c_uint32), ("sample", c_uint64), ("film_x", c_float),
                ("film_y", c_float), ("ray_kind", c_uint32), ("ray_depth", c_uint32), ("origin", float3),
                ("direction", float3), ("primitive", c_int32), ("t", c_float), ("value", c_float * 4)]


class DeviceShare(Structure):
    _fields_ = [("struct_size", c_size_t), ("units", c_uint64), ("samples", c_uint64), ("busy_seconds", c_double),
                ("failed", c_uint32), ("failure", c_char_p), ("device", c_char_p), ("film_bytes", c_uint64)]


class RenderStats(Structure):
    _fields_ = [("struct_size", c_size_t), ("seconds", c_double), ("kernel_build_seconds", c_double),
                ("primary_rays", c_uint64), ("reflected_rays", c_uint64), ("refracted_rays", c_uint64),
                ("shadow_rays", c_uint64), ("waves", c_uint32), ("rays_per_depth", c_uint64 * 32),
                ("accel", c_uint32), ("accel_build_seconds", c_double), ("rays_per_pixel", c_double),
                ("first_hit_used", c_uint32), ("setup_seconds", c_double), ("trace_seconds", c_double),
                ("shadows_used", c_uint32), ("first_launch_seconds", c_double)]


class Material(Structure):
    _fields_ = [("struct_size", c_size_t), ("model", c_uint32), ("ambient", float3), ("diffuse", float3),
                ("specular", float3), ("shininess", c_float), ("reflect", c_float), ("transmit", c_float),
                ("ior", c_float), ("gloss", c_float), ("translucency", c_float), ("checker", c_int),
                ("checker_color1", float3), ("checker_color2", float3), ("checker_scale", c_float),
                ("roughness", c_float), ("distribution", c_uint32)]


class Object(Structure):
    _fields_ = [("struct_size", c_size_t), ("type", c_uint32), ("material", c_char_p),
                ("object_to_world", POINTER(c_float)), ("object_to_world_end", POINTER(c_float)),
                ("center", float3), ("radius", c_float), ("box_min", float3), ("box_max", float3),
                ("point", float3), ("normal", float3), ("vertices", c_float * 9),
                ("coefficients", c_float * 10), ("clip_min", float3), ("clip_max", float3), ("capped", c_uint32)]


ProgressFn = CFUNCTYPE(c_int, c_void_p, c_double)

# name: (result type, argument types)
_FUNCTIONS = {
    "prismGetVersionString": (c_char_p, []),
    "prismGetLastError": (c_char_p, []),
    "prismStatusName": (c_char_p, [Status]),
    "prismGetDeviceCount": (Status, [POINTER(c_uint32)]),
    "prismGetDeviceInfo": (Status, [c_uint32, POINTER(DeviceInfo)]),
    "prismCreateContext": (Status, [c_char_p, c_void_p, POINTER(c_void_p)]),
    "prismReleaseContext": (None, [c_void_p]),
    "prismGetContextDevice": (Status, [c_void_p, POINTER(DeviceInfo)]),
    "prismGetContextDeviceCount": (Status, [c_void_p, POINTER(c_uint32)]),
    "prismGetContextDeviceAt": (Status, [c_void_p, c_uint32, POINTER(DeviceInfo)]),
    "prismGetRenderDeviceShareCount": (Status, [c_void_p, POINTER(c_uint32)]),
    "prismGetRenderDeviceShare": (Status, [c_void_p, c_uint32, POINTER(DeviceShare)]),
    "prismGetRenderWarningCount": (Status, [c_void_p, POINTER(c_uint32)]),
    "prismGetRenderWarning": (Status, [c_void_p, c_uint32, POINTER(c_char_p)]),
    "prismSetProgressCallback": (Status, [c_void_p, ProgressFn, c_void_p]),
    "prismLoadScene": (Status, [c_char_p, POINTER(c_void_p)]),
    "prismLoadSceneFromString": (Status, [c_char_p, c_char_p, POINTER(c_void_p)]),
    "prismLoadMeshAsScene": (Status, [c_char_p, POINTER(c_void_p)]),
    "prismNewScene": (Status, [POINTER(c_void_p)]),
    "prismReleaseScene": (None, [c_void_p]),
    "prismGetSceneWarningCount": (Status, [c_void_p, POINTER(c_uint32)]),
    "prismGetSceneObjectCount": (Status, [c_void_p, POINTER(c_uint32)]),
    "prismGetFrameCount": (Status, [c_void_p, POINTER(c_uint32)]),
    "prismGetFrameScene": (Status, [c_void_p, c_uint32, POINTER(c_void_p)]),
    "prismGetSceneDevice": (Status, [c_void_p, POINTER(c_char_p)]),
    "prismGetSceneWarning": (Status, [c_void_p, c_uint32, POINTER(c_char_p)]),
    "prismGetCamera": (Status, [c_void_p, POINTER(Camera)]),
    "prismSetCamera": (Status, [c_void_p, POINTER(Camera)]),
    "prismAddSceneJson": (Status, [c_void_p, c_char_p]),
    "prismDefaultMaterial": (None, [POINTER(Material)]),
    "prismAddMaterial": (Status, [c_void_p, c_char_p, POINTER(Material), POINTER(c_uint32)]),
    "prismDefaultObject": (None, [POINTER(Object), c_uint32]),
    "prismAddObject": (Status, [c_void_p, POINTER(Object), POINTER(c_uint32)]),
    "prismAddPointLight": (Status, [c_void_p, float3, float3, c_float]),
    "prismSetAmbient": (Status, [c_void_p, float3]),
    "prismSetBackground": (Status, [c_void_p, float3]),
    "prismAddMeshFile": (Status, [c_void_p, c_char_p, c_char_p, POINTER(c_float), c_int, POINTER(c_uint32)]),
    "prismAddMeshArrays": (Status, [c_void_p, c_void_p, c_size_t, c_void_p, c_size_t, c_char_p, POINTER(c_float),
                                    POINTER(c_uint32)]),
    "prismParseAccel": (Status, [c_char_p, POINTER(c_uint32)]),
    "prismParseAa": (Status, [c_char_p, POINTER(c_uint32)]),
    "prismParseFilter": (Status, [c_char_p, POINTER(c_uint32)]),
    "prismParseFirstHit": (Status, [c_char_p, POINTER(c_uint32)]),
    "prismParseInsideTest": (Status, [c_char_p, POINTER(c_uint32)]),
    "prismParseShadows": (Status, [c_char_p, POINTER(c_uint32)]),
    "prismShadowsName": (c_char_p, [c_uint32]),
    "prismParseBounds": (Status, [c_char_p, POINTER(c_uint32)]),
    "prismBoundsName": (c_char_p, [c_uint32]),
    "prismParseAov": (Status, [c_char_p, POINTER(c_uint32)]),
    "prismGetAovChannels": (Status, [c_uint32, POINTER(c_uint32)]),
    "prismGetRenderOptions": (Status, [c_void_p, POINTER(RenderOptions)]),
    "prismCheckRenderOptions": (Status, [POINTER(RenderOptions)]),
    "prismRender": (Status, [c_void_p, c_void_p, POINTER(RenderOptions), c_void_p, POINTER(RenderStats)]),
    "prismGetAov": (Status, [c_void_p, c_uint32, c_void_p, c_size_t]),
    "prismGetNanReport": (Status, [c_void_p, POINTER(NanReport)]),
    "prismIntersect": (Status, [c_void_p, c_void_p, c_uint32, c_void_p, c_void_p, c_size_t, POINTER(c_double)]),
    "prismOccluded": (Status, [c_void_p, c_void_p, c_uint32, c_void_p, c_void_p, c_size_t, POINTER(c_double)]),
    "prismWriteImage": (Status, [c_char_p, c_void_p, c_uint32, c_uint32, c_uint32]),
}
for _name, (_result, _arguments) in _FUNCTIONS.items():
    _f = getattr(lib, _name)
    _f.restype = _result
    _f.argtypes = _arguments


class Error(Exception):
    """A prism call failed; the message is prism's own, `status` its status name."""

    def __init__(self, message, status):
        super().__init__(message)
        self.status = status


class InvalidArgumentError(Error, ValueError):
    """A bad argument: a value out of range, an unknown name, a bad array."""


class FileError(Error, OSError):
    """A file could not be read or written."""


class ParseError(Error, ValueError):
    """A scene or mesh file is malformed or holds a value prism refuses."""


class DeviceError(Error):
    """No such OpenCL device, or an OpenCL call failed."""


class KernelBuildError(Error):
    """A kernel failed to compile; the message holds the build log."""


class Cancelled(Error):
    """A progress callback asked to stop (or another invalid operation)."""


_BY_STATUS = {1: InvalidArgumentError, 2: FileError, 3: ParseError, 4: DeviceError, 5: KernelBuildError,
              6: MemoryError, 7: Cancelled}


def check(status):
    """Raises the exception for a failed call's status, carrying prism's message."""
    if status == 0:
        return
    message = (lib.prismGetLastError() or b"").decode("utf-8", "replace")
    name = lib.prismStatusName(status).decode()
    kind = _BY_STATUS.get(status, Error)
    if kind is MemoryError:
        raise MemoryError(message)
    raise kind(message, name)


def enum_value(parser, name, what):
    value = c_uint32()
    check(parser(name.encode(), ctypes.byref(value)))
    return value.value


def matrix(values):
    """A 4x4 row-major matrix as 16 floats for the C API, or None."""
    if values is None:
        return None
    flat = [float(x) for row in values for x in (row if hasattr(row, "__len__") else [row])]
    if len(flat) != 16:
        raise InvalidArgumentError("a transform must be a 4x4 matrix (16 numbers, row-major), got %d numbers"
                                   % len(flat), "PRISM_ERROR_INVALID_ARGUMENT")
    return (c_float * 16)(*flat)


__all__ = ["lib", "check"]
