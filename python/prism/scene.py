"""prism.Scene: a scene loaded from a file, a mesh or JSON, or built in code.
Every addition is checked by prism's scene loader, with its messages."""

import ctypes
import json as _json
import operator
import os

import numpy as np

from . import _capi
from ._capi import check, lib

_SHADING = {"phong": 0, "blinn": 1, "cook-torrance": 2}
_MICROFACET = {"beckmann": 0, "ggx": 1}
_OBJECT = {"sphere": 0, "box": 1, "plane": 2, "triangle": 3, "quadric": 4}


def _triple(values, what):
    v = [float(x) for x in values]
    if len(v) != 3:
        raise _capi.InvalidArgumentError("%s: expected 3 numbers, got %d" % (what, len(v)),
                                         "PRISM_ERROR_INVALID_ARGUMENT")
    return _capi.float3(*v)


class Scene:
    """A scene. `Scene()` is empty (default camera and material, no lights);
    `Scene.load(path)`, `Scene.from_json(text_or_dict)` and `Scene.from_mesh(path)`
    read one. A scene belongs to no device: any Context can render it."""

    def __init__(self, _handle=None):
        if _handle is None:
            handle = ctypes.c_void_p()
            check(lib.prismNewScene(ctypes.byref(handle)))
            _handle = handle
        self._handle = _handle

    @classmethod
    def load(cls, path):
        """Reads a scene file (docs/scene-format.md); mesh paths are relative to it."""
        handle = ctypes.c_void_p()
        check(lib.prismLoadScene(os.fsencode(path), ctypes.byref(handle)))
        return cls(handle)

    @classmethod
    def from_json(cls, scene, name="<python>"):
        """A scene from scene-format text or a dict of the same shape."""
        text = scene if isinstance(scene, str) else _json.dumps(scene)
        handle = ctypes.c_void_p()
        check(lib.prismLoadSceneFromString(text.encode(), name.encode(), ctypes.byref(handle)))
        return cls(handle)

    @classmethod
    def from_mesh(cls, path):
        """A scene showing one mesh file: a framing camera, a headlight."""
        handle = ctypes.c_void_p()
        check(lib.prismLoadMeshAsScene(os.fsencode(path), ctypes.byref(handle)))
        return cls(handle)

    def __del__(self):
        handle, self._handle = getattr(self, "_handle", None), None
        if handle:
            lib.prismReleaseScene(handle)

    @property
    def warnings(self):
        """What the loader noticed but accepted (unknown keys and the like)."""
        count = ctypes.c_uint32()
        check(lib.prismGetSceneWarningCount(self._handle, ctypes.byref(count)))
        out = []
        for i in range(count.value):
            text = ctypes.c_char_p()
            check(lib.prismGetSceneWarning(self._handle, i, ctypes.byref(text)))
            out.append(text.value.decode("utf-8", "replace"))
        return out

    @property
    def device(self):
        """The devices the scene asks to render on (render.device: a selector
        such as "all" or "0,2"), or None when it names none."""
        text = ctypes.c_char_p()
        check(lib.prismGetSceneDevice(self._handle, ctypes.byref(text)))
        return text.value.decode() if text.value else None

    @property
    def frame_count(self):
        """The frames of the scene's animation (its "animation" block); 1 for a still."""
        count = ctypes.c_uint32()
        check(lib.prismGetFrameCount(self._handle, ctypes.byref(count)))
        return count.value

    def frame(self, index):
        """Frame `index` (from 0) of the animation as a scene of its own: the
        shutter moved by index x step, the moving objects and camera placed on
        their path for it. Render it as any scene."""
        if isinstance(index, bool):
            raise TypeError("frame: expected a frame number, got %r" % (index,))
        index = operator.index(index)  # ints and NumPy integers; TypeError otherwise
        if not 0 <= index < self.frame_count:
            raise ValueError("frame: the scene has frames 0 to %d, got %d" % (self.frame_count - 1, index))
        handle = ctypes.c_void_p()
        check(lib.prismGetFrameScene(self._handle, index, ctypes.byref(handle)))
        return Scene(handle)

    @property
    def object_count(self):
        """The objects so far: the index the next object added gets."""
        count = ctypes.c_uint32()
        check(lib.prismGetSceneObjectCount(self._handle, ctypes.byref(count)))
        return count.value

    # ---- building -------------------------------------------------------------

    def add(self, fragment):
        """Adds a scene-format fragment (a dict or JSON text with any of camera,
        film, render, materials, lights, objects): every kind the format has."""
        text = fragment if isinstance(fragment, str) else _json.dumps(fragment)
        check(lib.prismAddSceneJson(self._handle, text.encode()))
        return self

    def add_material(self, name, model="phong", ambient=None, diffuse=None, specular=None, shininess=None,
                     reflect=None, transmit=None, ior=None, gloss=None, translucency=None, checker=None,
                     roughness=None, distribution="beckmann"):
        """Adds a material; unnamed arguments keep the scene format's defaults
        (model phong, blinn or cook-torrance; for cook-torrance `roughness`,
        `distribution` beckmann or ggx, and ior 1.5 unless given). `checker`:
        (color1, color2, scale) for a checker texture. Returns its index."""
        m = _capi.Material()
        lib.prismDefaultMaterial(ctypes.byref(m))
        if model not in _SHADING:
            raise _capi.InvalidArgumentError("model: expected phong, blinn or cook-torrance, got %r" % (model,),
                                             "PRISM_ERROR_INVALID_ARGUMENT")
        m.model = _SHADING[model]
        if model == "cook-torrance":
            if ior is None:
                ior = 1.5  # the scene format's default for this model
            if roughness is not None:
                m.roughness = float(roughness)
            if distribution not in _MICROFACET:
                raise _capi.InvalidArgumentError("distribution: expected beckmann or ggx, got %r" % (distribution,),
                                                 "PRISM_ERROR_INVALID_ARGUMENT")
            m.distribution = _MICROFACET[distribution]
        for field, value in (("ambient", ambient), ("diffuse", diffuse), ("specular", specular)):
            if value is not None:
                setattr(m, field, _triple(np.broadcast_to(value, 3), field))
        for field, value in (("shininess", shininess), ("reflect", reflect), ("transmit", transmit), ("ior", ior),
                             ("gloss", gloss), ("translucency", translucency)):
            if value is not None:
                setattr(m, field, float(value))
        if checker is not None:
            color1, color2, scale = checker
            m.checker = 1
            m.checker_color1 = _triple(color1, "checker color1")
            m.checker_color2 = _triple(color2, "checker color2")
            m.checker_scale = float(scale)
        index = ctypes.c_uint32()
        check(lib.prismAddMaterial(self._handle, name.encode(), ctypes.byref(m), ctypes.byref(index)))
        return index.value

    def _add_object(self, kind, material, transform, transform_end, **fields):
        o = _capi.Object()
        lib.prismDefaultObject(ctypes.byref(o), _OBJECT[kind])
        for field, value in fields.items():
            if field == "vertices":
                flat = np.asarray(value, dtype=np.float32).reshape(-1)
                if flat.size != 9:
                    raise _capi.InvalidArgumentError("vertices: expected 3 points", "PRISM_ERROR_INVALID_ARGUMENT")
                o.vertices = (ctypes.c_float * 9)(*flat.tolist())
            elif field == "coefficients":
                flat = np.asarray(value, dtype=np.float32).reshape(-1)
                if flat.size != 10:
                    raise _capi.InvalidArgumentError("coefficients: expected 10 numbers (A..J)",
                                                     "PRISM_ERROR_INVALID_ARGUMENT")
                o.coefficients = (ctypes.c_float * 10)(*flat.tolist())
            elif field == "capped":
                o.capped = 1 if value else 0
            elif field == "radius":
                o.radius = float(value)
            else:
                setattr(o, field, _triple(value, field))
        keep = (_capi.matrix(transform), _capi.matrix(transform_end))  # alive until the call returns
        o.object_to_world, o.object_to_world_end = keep
        o.material = material.encode() if material is not None else None
        index = ctypes.c_uint32()
        check(lib.prismAddObject(self._handle, ctypes.byref(o), ctypes.byref(index)))
        return index.value

    def add_sphere(self, center, radius, material=None, transform=None, transform_end=None):
        """Adds a sphere; returns its object index. `transform`, `transform_end`:
        4x4 row-major object-to-world matrices (the second: at shutter close)."""
        return self._add_object("sphere", material, transform, transform_end, center=center, radius=radius)

    def add_box(self, box_min, box_max, material=None, transform=None, transform_end=None):
        return self._add_object("box", material, transform, transform_end, box_min=box_min, box_max=box_max)

    def add_plane(self, point, normal, material=None, transform=None, transform_end=None):
        return self._add_object("plane", material, transform, transform_end, point=point, normal=normal)

    def add_triangle(self, vertices, material=None, transform=None, transform_end=None):
        return self._add_object("triangle", material, transform, transform_end, vertices=vertices)

    def add_quadric(self, coefficients, clip_min, clip_max, capped=False, material=None, transform=None,
                    transform_end=None):
        """Adds the quadric A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0
        (`coefficients` A..J) inside the box [clip_min, clip_max]; `capped`: the solid where it is
        <= 0, closed by the box's faces. Presets (cylinder, cone, ...): `add({"objects": [...]})`."""
        return self._add_object("quadric", material, transform, transform_end, coefficients=coefficients,
                                clip_min=clip_min, clip_max=clip_max, capped=capped)

    def add_polygon(self, vertices, inside_test=None, material=None, transform=None, transform_end=None):
        """Adds a planar polygon, convex or not (vertices: (N, 3), N >= 3, in order);
        `inside_test`: "crossing", "radial" or "left-right" (convex only), else the
        render's. Returns its object index."""
        obj = {"type": "polygon", "vertices": np.asarray(vertices, dtype=np.float64).reshape(-1, 3).tolist()}
        if inside_test is not None:
            obj["inside_test"] = inside_test
        return self._add_json_object(obj, material, transform, transform_end)

    def add_polyhedron(self, planes, material=None, transform=None, transform_end=None):
        """Adds the convex polyhedron where a x + b y + c z + d <= 0 for every plane
        [a, b, c, d] of `planes` ((N, 4), N >= 4; bounded). Returns its object index."""
        obj = {"type": "polyhedron", "planes": np.asarray(planes, dtype=np.float64).reshape(-1, 4).tolist()}
        return self._add_json_object(obj, material, transform, transform_end)

    def add_patches(self, control_points=None, file=None, method="subdivision", tolerance=None, material=None,
                    transform=None, transform_end=None):
        """Adds bicubic Bezier patches: `control_points` ((N, 16, 3): each patch's 4 x 4 net,
        i along u then j along v, as a .bpt file lists them) or a .bpt `file`. `method`:
        "subdivision" (triangles within `tolerance` of the surface) or "analytic" (Newton
        iteration on patch pieces, to `tolerance` from the ray); `tolerance` None: the
        method's default (docs/scene-format.md, Bezier patches). Returns its object index."""
        if (control_points is None) == (file is None):
            raise ValueError("add_patches: give control_points or file, not both or neither")
        obj = {"type": "patches", "method": method}
        if file is not None:
            obj["file"] = str(file)
        else:
            obj["patches"] = np.asarray(control_points, dtype=np.float64).tolist()  # prism checks the shape
        if tolerance is not None:
            obj["tolerance"] = float(tolerance)
        return self._add_json_object(obj, material, transform, transform_end)

    def _add_json_object(self, obj, material, transform, transform_end):
        if material is not None:
            obj["material"] = material
        for key, m in (("transform", transform), ("transform_end", transform_end)):
            if m is not None:
                obj[key] = {"matrix": [float(x) for x in _capi.matrix(m)]}
        self.add({"objects": [obj]})
        return self.object_count - 1

    def add_mesh(self, positions, triangles, material=None, transform=None):
        """Adds a triangle mesh from arrays (copied): positions (N, 3) float,
        triangles (M, 3) vertex indices. Returns its object index."""
        p = np.ascontiguousarray(positions, dtype=np.float32).reshape(-1, 3)
        t = np.ascontiguousarray(triangles, dtype=np.uint32).reshape(-1, 3)
        index = ctypes.c_uint32()
        check(lib.prismAddMeshArrays(self._handle, p.ctypes.data, p.shape[0], t.ctypes.data, t.shape[0],
                                     material.encode() if material is not None else None,
                                     _capi.matrix(transform), ctypes.byref(index)))
        return index.value

    def add_mesh_file(self, path, material=None, transform=None, smooth=False):
        """Adds a mesh file read by the format plugins (OBJ, PLY, OFF)."""
        index = ctypes.c_uint32()
        check(lib.prismAddMeshFile(self._handle, os.fsencode(path), material.encode() if material else None,
                                   _capi.matrix(transform), 1 if smooth else 0, ctypes.byref(index)))
        return index.value

    def add_point_light(self, position, color=(1, 1, 1), intensity=1.0):
        check(lib.prismAddPointLight(self._handle, _triple(position, "position"), _triple(color, "color"),
                                     float(intensity)))
        return self

    def set_background(self, color):
        check(lib.prismSetBackground(self._handle, _triple(np.broadcast_to(color, 3), "background")))
        return self

    def set_ambient(self, color):
        check(lib.prismSetAmbient(self._handle, _triple(np.broadcast_to(color, 3), "ambient")))
        return self

    # ---- camera ---------------------------------------------------------------

    @property
    def camera(self):
        """The camera as a dict (position, look_at, up, fov, aperture,
        focus_distance, shutter); assign a dict with any of these keys to change it."""
        c = self._get_camera()
        return {"position": tuple(c.position), "look_at": tuple(c.look_at), "up": tuple(c.up),
                "fov": c.fov_degrees, "aperture": c.aperture, "focus_distance": c.focus_distance,
                "shutter": (c.shutter_open, c.shutter_close)}

    @camera.setter
    def camera(self, values):
        c = self._get_camera()
        for key, value in values.items():
            if key in ("position", "look_at", "up"):
                setattr(c, key, _triple(value, key))
            elif key == "fov":
                c.fov_degrees = float(value)
            elif key in ("aperture", "focus_distance"):
                setattr(c, key, float(value))
            elif key == "shutter":
                c.shutter_open, c.shutter_close = (float(x) for x in value)
            else:
                raise _capi.InvalidArgumentError("camera: unknown key %r" % (key,), "PRISM_ERROR_INVALID_ARGUMENT")
        check(lib.prismSetCamera(self._handle, ctypes.byref(c)))

    def _get_camera(self):
        c = _capi.Camera()
        c.struct_size = ctypes.sizeof(c)
        check(lib.prismGetCamera(self._handle, ctypes.byref(c)))
        return c
