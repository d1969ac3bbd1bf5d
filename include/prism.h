/* prism.h -- the public C API of the prism ray tracer (C99).
 *
 * Every call returns a PrismStatus (or nothing) and never aborts or throws. After a
 * failed call, prismGetLastError() returns a message for the calling thread that names
 * the file, key or argument at fault and the reason.
 *
 * Ownership: handles (PrismContext, PrismScene, PrismResult, PrismMeshReport) are
 * opaque; each is made by one call, belongs to the caller, and is released once by its
 * Release call (NULL is a no-op). There is no reference counting, and none is needed:
 * no handle keeps another alive or points at it, so they may be released in any order
 * (a result outlives its context and scene; a scene may be released while contexts
 * that rendered it live). Strings returned as const char* belong to the library; each
 * function says how long they stay valid. Buffers passed in are the caller's and are
 * copied or written before the call returns.
 *
 * Threads: calls on one context must not overlap (use a context from one thread at a
 * time); different contexts may be used from different threads at once, also on one
 * shared scene, as long as no thread changes that scene meanwhile. A scene is changed
 * only by the calls that take it to add or set something. Calls without a context or
 * scene (devices, names, scene loading, prismWriteImage) may be made from any thread.
 * docs/c-api.md, "Threads and ownership", and tests/api/c_api_threads_test.c.
 *
 * Typical use:
 *   PrismContext ctx;  prismCreateContext(NULL, NULL, &ctx);
 *   PrismScene scene;  prismLoadScene("scene.json", &scene);
 *   PrismRenderOptions opts;  opts.struct_size = sizeof opts;  prismGetRenderOptions(scene, &opts);
 *   float* rgba = malloc(4 * sizeof(float) * opts.width * opts.height);
 *   prismRender(ctx, scene, &opts, rgba, NULL);
 *   prismWriteImage("out.png", rgba, opts.width, opts.height, 4);
 */
#ifndef PRISM_H
#define PRISM_H

#include <stddef.h>
#include <stdint.h>

#include "prism_config.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum PrismStatus {
  PRISM_OK = 0,
  PRISM_ERROR_INVALID_ARGUMENT = 1, /* a NULL handle, a bad size, an unknown name */
  PRISM_ERROR_IO = 2,               /* a file could not be read or written */
  PRISM_ERROR_PARSE = 3,            /* a scene file is malformed or holds bad values */
  PRISM_ERROR_DEVICE = 4,           /* no such OpenCL device, or an OpenCL call failed */
  PRISM_ERROR_KERNEL_BUILD = 5,     /* a kernel failed to compile; the message holds the log */
  PRISM_ERROR_OUT_OF_MEMORY = 6,
  PRISM_ERROR_INVALID_OPERATION = 7, /* e.g. reading an AOV before any render */
  PRISM_ERROR_UNKNOWN = 8
} PrismStatus;

typedef struct PrismContextImpl* PrismContext; /* one OpenCL device, its queue and programs */
typedef struct PrismSceneImpl* PrismScene;     /* a loaded scene, independent of any device */

/* ---- version and errors ------------------------------------------------------ */

/* The library's version as major << 16 | minor << 8 | patch. */
PRISM_API uint32_t prismGetVersion(void);
/* The library's version as "major.minor.patch". */
PRISM_API const char* prismGetVersionString(void);
/* The message of the last failed call on this thread ("" if none). Valid until the
 * next failing call on the same thread. */
PRISM_API const char* prismGetLastError(void);
/* A short constant name for a status code, e.g. "PRISM_ERROR_PARSE". */
PRISM_API const char* prismStatusName(PrismStatus status);

/* ---- devices -------------------------------------------------------------------- */

typedef enum PrismDeviceType {
  PRISM_DEVICE_CPU = 1,
  PRISM_DEVICE_GPU = 2,
  PRISM_DEVICE_ACCELERATOR = 4,
  PRISM_DEVICE_OTHER = 8
} PrismDeviceType;

typedef struct PrismDeviceInfo {
  uint32_t index;                /* the number --device N selects */
  char name[256];
  char vendor[256];
  char platform[256];
  char driver_version[128];
  char opencl_c_version[128];
  PrismDeviceType type;
  uint32_t compute_units;
  uint64_t global_memory_bytes;
} PrismDeviceInfo;

/* Number of OpenCL devices over all platforms (0 when there is no OpenCL runtime). */
PRISM_API PrismStatus prismGetDeviceCount(uint32_t* count);
/* Description of device `index` (0-based, in the order prismGetDeviceCount counts). */
PRISM_API PrismStatus prismGetDeviceInfo(uint32_t index, PrismDeviceInfo* info);

/* ---- contexts ------------------------------------------------------------------ */

typedef struct PrismContextOptions {
  size_t struct_size;   /* sizeof(PrismContextOptions); set by prismDefaultContextOptions */
  int use_kernel_cache; /* nonzero: keep compiled kernels in the on-disk cache (default 1) */
} PrismContextOptions;

PRISM_API void prismDefaultContextOptions(PrismContextOptions* options);

/* Creates a context on the device chosen by `selector`: NULL or "" for the default
 * (the first GPU, else the first device), a decimal index, "cpu", "gpu", or a
 * case-insensitive substring of the device name; or on several devices, which
 * share each frame: "all", or a comma-separated list of such selectors ("0,2";
 * no device twice). The first of them resolves the frame and answers ray
 * queries. `options` may be NULL. */
PRISM_API PrismStatus prismCreateContext(const char* selector, const PrismContextOptions* options,
                                         PrismContext* out_context);
PRISM_API void prismReleaseContext(PrismContext context); /* NULL is a no-op */
/* The description of the context's (first) device. */
PRISM_API PrismStatus prismGetContextDevice(PrismContext context, PrismDeviceInfo* info);
/* How many devices the context deals its frames over, and each of them (position
 * 0 is the first, the one prismGetContextDevice describes). */
PRISM_API PrismStatus prismGetContextDeviceCount(PrismContext context, uint32_t* count);
PRISM_API PrismStatus prismGetContextDeviceAt(PrismContext context, uint32_t position, PrismDeviceInfo* info);

/* Called during prismRender with the fraction of work done (0..1); return nonzero
 * to cancel the render (prismRender then fails with PRISM_ERROR_INVALID_OPERATION). */
typedef int (*PrismProgressFn)(void* user, double fraction_done);
PRISM_API PrismStatus prismSetProgressCallback(PrismContext context, PrismProgressFn fn, void* user);

/* Several processes (MPI ranks, say) can share each frame. Each creates a
 * context on its own devices, gives it the same `parts` and its own `part`, and
 * calls prismRender with the same scene and options; each traces a contiguous
 * stretch of the frame's units, and part 0's prismRender returns the whole
 * image, AOVs and counts, bit for bit those of one process on devices of the
 * same kind (the other parts' image and AOVs hold zeros, primid -1). Every part
 * first checks that all render the same frame (options, camera, mesh data);
 * if not, prismRender fails on every part with PRISM_ERROR_INVALID_ARGUMENT.
 * The transport is the caller's: prismRender calls `exchange` on every part in
 * the same order, with this part's bytes; when `to_all` is nonzero every part
 * must receive every part's bytes, otherwise part 0 alone does;
 * `receive(receiver, part, data, size)` is called once for each part whose
 * bytes arrive here (this part's own included). It returns 0, or nonzero when
 * the transport failed (prismRender then fails with PRISM_ERROR_UNKNOWN). A
 * part whose prismRender fails for any other reason (its device, a cancel)
 * leaves the others waiting at their next exchange: end them, as `prism
 * render` does with MPI_Abort. The parts run one build of prism on machines of
 * one byte order. A NULL `parts` makes the context render alone again.
 *
 * Without `compare_swap` each part traces an equal stretch of the units, so the
 * frame waits for the slowest part. With it, the units are dealt as each
 * part's devices come free: a part takes from the front of its own stretch,
 * then from the back of the stretch with the most left (the image is the same
 * bits either way). `compare_swap` is an atomic compare-and-swap on word `word`
 * (below `parts`) of `parts` 64-bit words that every part sees and that are
 * zero when prismSetFrameParts is called (fresh words for each call): it sets
 * `*found` to the word's value and, if that was `expected`, sets the word to
 * `desired`. It returns 0, or nonzero when the transport failed. prismRender
 * may call it from any of its threads, never two calls at once; each part
 * calls it on its own schedule, so it must not wait for the others (MPI:
 * MPI_Compare_and_swap on a window, as `prism render` does; where the
 * transport completes it only while the window's owner is inside MPI, as Open
 * MPI's over TCP does, the owner must keep calling MPI meanwhile: `prism
 * render` runs a thread on part 0 that does). */
typedef void (*PrismReceiveFn)(void* receiver, uint32_t part, const void* data, uint64_t size);
typedef int (*PrismExchangeFn)(void* user, int to_all, const void* data, uint64_t size, PrismReceiveFn receive,
                               void* receiver);
typedef int (*PrismCompareSwapFn)(void* user, uint32_t word, uint64_t expected, uint64_t desired, uint64_t* found);
typedef struct PrismFrameParts {
  size_t struct_size;       /* sizeof(PrismFrameParts) */
  uint32_t part;            /* this process, below parts; 0 gets the image */
  uint32_t parts;           /* processes sharing each frame (1: alone) */
  PrismExchangeFn exchange; /* needed when parts > 1 */
  void* user;               /* passed to exchange and compare_swap */
  PrismCompareSwapFn compare_swap; /* optional (NULL: equal stretches); all parts give it or none */
} PrismFrameParts;
PRISM_API PrismStatus prismSetFrameParts(PrismContext context, const PrismFrameParts* parts);

/* ---- scenes -------------------------------------------------------------------- */

/* Loads a JSON scene file (docs/scene-format.md). */
PRISM_API PrismStatus prismLoadScene(const char* path, PrismScene* out_scene);
/* Parses a scene from JSON text; `name` stands for the file in error messages. */
PRISM_API PrismStatus prismLoadSceneFromString(const char* json, const char* name, PrismScene* out_scene);
PRISM_API void prismReleaseScene(PrismScene scene); /* NULL is a no-op */
/* The devices the scene asks to render on (render.device: a selector as
 * prismCreateContext takes, "" when it names none); owned by the scene. A
 * caller that lets the scene choose passes it to prismCreateContext. */
PRISM_API PrismStatus prismGetSceneDevice(PrismScene scene, const char** selector);
/* Warnings found while loading (unknown keys and the like), one per index. */
PRISM_API PrismStatus prismGetSceneWarningCount(PrismScene scene, uint32_t* count);
PRISM_API PrismStatus prismGetSceneWarning(PrismScene scene, uint32_t index, const char** message);
/* An animation (the scene format's "animation": frames whose shutters follow
 * one another by a step, the scene's motion spanning all of them): how many
 * frames it has (1 for a still), and frame `frame` (0-based) as a scene of its
 * own, released with prismReleaseScene, which renders as any scene does.
 * prismRender and the ray queries given the animation itself use its frame 0. */
PRISM_API PrismStatus prismGetFrameCount(PrismScene scene, uint32_t* count);
PRISM_API PrismStatus prismGetFrameScene(PrismScene scene, uint32_t frame, PrismScene* out_scene);
/* The scene's objects so far (the index the next object added will get). */
PRISM_API PrismStatus prismGetSceneObjectCount(PrismScene scene, uint32_t* count);

/* The camera (DESIGN.md: right-handed; pixel (i, j) with i to the right, j down
 * from the top row; one sample goes through the pixel centre). A pinhole unless
 * it has an aperture (depth of field) or a shutter interval (motion blur; the
 * camera itself moves when `moving` is nonzero). docs/scene-format.md, "camera". */
typedef struct PrismCamera {
  size_t struct_size; /* sizeof(PrismCamera); set by prismGetCamera */
  float position[3];
  float look_at[3];
  float up[3];
  float fov_degrees;  /* vertical field of view, 0 < fov < 180 */
  float aperture;       /* lens radius in scene units; 0: a pinhole */
  float focus_distance; /* distance of the plane in focus along the view direction; 0: to look_at */
  float shutter_open, shutter_close; /* the shutter interval; equal: an instant */
  int moving;           /* nonzero: at shutter close the camera is at position_end looking at look_at_end */
  float position_end[3];
  float look_at_end[3];
} PrismCamera;

/* The scene's camera, to read or change (prismSetCamera checks it: position !=
 * look_at, up not parallel to the view direction, fov in (0, 180), aperture and
 * focus_distance >= 0, shutter_close >= shutter_open; the same rules and
 * messages as the scene format's camera). */
PRISM_API PrismStatus prismGetCamera(PrismScene scene, PrismCamera* camera);
PRISM_API PrismStatus prismSetCamera(PrismScene scene, const PrismCamera* camera);

/* ---- meshes -------------------------------------------------------------------- */

/* Mesh files are read by format plugins (include/prism_plugin.h, docs/plugins.md):
 * OBJ with MTL, PLY and OFF ship with prism. */

/* An empty scene (default camera and material, no lights or objects) to build
 * through the calls below. */
PRISM_API PrismStatus prismNewScene(PrismScene* out_scene);
/* A scene showing one mesh file, as `prism render MESH` does: a camera framing its
 * bounding box, a headlight, a default material. Fails for a file with no
 * triangles or with vertices past 1e15 in magnitude; a mesh too large for a
 * camera of coordinates within 1e15 to show whole is shown from closer, with a
 * warning. */
PRISM_API PrismStatus prismLoadMeshAsScene(const char* path, PrismScene* out_scene);
/* Adds a point light. */
PRISM_API PrismStatus prismAddPointLight(PrismScene scene, const float position[3], const float color[3],
                                         float intensity);

typedef enum PrismAreaLightType { PRISM_LIGHT_QUAD = 1, PRISM_LIGHT_DISK = 2, PRISM_LIGHT_SPHERE = 3 } PrismAreaLightType;

/* An area light of uniform emitted radiance color x intensity (docs/scene-format.md,
 * "lights"): a quad (corner + the parallelogram of edge1 and edge2), a disk
 * (center, normal, radius) or a sphere (center, radius); fields another type
 * uses are ignored. `samples`: shadow feelers per pixel it wants (1 to 4096). */
typedef struct PrismAreaLight {
  size_t struct_size; /* sizeof(PrismAreaLight) */
  PrismAreaLightType type;
  float corner[3], edge1[3], edge2[3];
  float center[3], normal[3];
  float radius;
  float color[3];
  float intensity;
  int samples;
} PrismAreaLight;

/* Adds an area light; the same checks and messages as the scene loader's. */
PRISM_API PrismStatus prismAddAreaLight(PrismScene scene, const PrismAreaLight* light);
/* Adds a mesh object from a file. `material` names a material of the scene (NULL:
 * the file's own materials); `object_to_world` is a 4x4 row-major affine matrix
 * (NULL: identity; the scene format's rule: invertible, its entries and its
 * inverse's at most 1e15 in magnitude); `smooth` nonzero interpolates the file's vertex normals.
 * Several objects naming one file share its data. `out_object` (may be NULL)
 * receives the object's index. */
PRISM_API PrismStatus prismAddMeshFile(PrismScene scene, const char* path, const char* material,
                                       const float* object_to_world, int smooth, uint32_t* out_object);
/* Adds a mesh from caller-owned arrays, which are copied: `positions` holds
 * vertex_count xyz triples, `indices` 3 per triangle. Same checks as a file; for
 * both, the vertices that faces use must lie within 1e15 in magnitude once
 * placed by `object_to_world`. */
PRISM_API PrismStatus prismAddMeshArrays(PrismScene scene, const float* positions, size_t vertex_count,
                                         const uint32_t* indices, size_t triangle_count, const char* material,
                                         const float* object_to_world, uint32_t* out_object);

/* ---- building a scene in code --------------------------------------------------- */

/* The calls below go through the scene loader's own checks (one implementation
 * behind both): a value a scene file may not hold is refused with the file's
 * message, naming the element as a file would (`objects[3].radius: expected a
 * positive number, got -1`; indices are the element's place in the scene), and
 * the scene is left as it was. docs/scene-format.md has every key and rule. */

/* Adds a fragment of the scene format: a JSON object with any of camera, film,
 * render, materials, lights, objects. Lights and objects are appended, materials
 * added by name (a name may be taken once; "default" replaces the built-in
 * material), and the camera, film and render keys given replace the scene's.
 * Relative mesh file names are found from the current directory. Every kind the
 * format has, now and later, can be added this way. PRISM_ERROR_PARSE for
 * malformed JSON or a refused value. */
PRISM_API PrismStatus prismAddSceneJson(PrismScene scene, const char* json);

typedef enum PrismShadingModel {
  PRISM_SHADING_PHONG = 0,
  PRISM_SHADING_BLINN = 1,
  PRISM_SHADING_COOK_TORRANCE = 2 /* roughness, distribution; Fresnel from ior */
} PrismShadingModel;
typedef enum PrismMicrofacet { PRISM_MICROFACET_BECKMANN = 0, PRISM_MICROFACET_GGX = 1 } PrismMicrofacet;

/* A material of the Whitted model (docs/scene-format.md, "materials"). */
typedef struct PrismMaterial {
  size_t struct_size; /* sizeof(PrismMaterial); set by prismDefaultMaterial */
  uint32_t model;     /* a PrismShadingModel */
  float ambient[3];   /* multiplies the scene's ambient light */
  float diffuse[3];
  float specular[3];
  float shininess;    /* specular exponent, 0..1e6 */
  float reflect;      /* weight of the mirror ray, 0..1 */
  float transmit;     /* weight of the refracted ray and of shadow transmission, 0..1 */
  float ior;          /* index of refraction of the inside, > 0; Cook-Torrance's Fresnel factor
                         too (prismDefaultMaterial gives Phong's 1, which reflects nothing there:
                         set about 1.5 for a plastic) */
  float gloss;        /* Phong-lobe exponent of reflected rays; 0: a perfect mirror */
  float translucency; /* the same for refracted rays; 0: clear */
  int checker;        /* nonzero: a checker texture multiplies ambient and diffuse */
  float checker_color1[3], checker_color2[3];
  float checker_scale; /* size of one square in surface units, in [1e-15, 1e15] */
  float roughness;      /* Cook-Torrance: Beckmann's m or GGX's alpha, 0.001..1 */
  uint32_t distribution; /* Cook-Torrance: a PrismMicrofacet */
} PrismMaterial;

/* Fills `material` with the defaults a scene file's material starts from. */
PRISM_API void prismDefaultMaterial(PrismMaterial* material);
/* Adds a material under `name`, for objects to name; `out_material` (may be
 * NULL) receives its index. */
PRISM_API PrismStatus prismAddMaterial(PrismScene scene, const char* name, const PrismMaterial* material,
                                       uint32_t* out_material);

typedef enum PrismObjectType {
  PRISM_OBJECT_SPHERE = 0,  /* center, radius */
  PRISM_OBJECT_BOX = 1,     /* box_min, box_max */
  PRISM_OBJECT_PLANE = 2,   /* point, normal */
  PRISM_OBJECT_TRIANGLE = 3, /* vertices */
  PRISM_OBJECT_QUADRIC = 4   /* coefficients, clip_min, clip_max, capped; presets: prismAddSceneJson */
} PrismObjectType;

/* An analytic object (meshes: prismAddMeshFile, prismAddMeshArrays); only the
 * fields of its type are read. */
typedef struct PrismObject {
  size_t struct_size;   /* sizeof(PrismObject); set by prismDefaultObject */
  uint32_t type;        /* a PrismObjectType */
  const char* material; /* a material's name; NULL: the default material */
  const float* object_to_world;     /* 4x4 row-major affine matrix, or NULL for the identity */
  const float* object_to_world_end; /* motion blur: the matrix at shutter close, or NULL (not moving) */
  float center[3];
  float radius;
  float box_min[3], box_max[3];
  float point[3], normal[3];
  float vertices[9]; /* three xyz points */
  /* A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0 inside
   * the box [clip_min, clip_max]; capped (non-zero): the solid {<= 0} closed by
   * the box's faces, else the open surface (docs/scene-format.md, quadrics). */
  float coefficients[10];
  float clip_min[3], clip_max[3];
  uint32_t capped;
} PrismObject;

/* Fills `object` with struct_size, `type`, and zero everywhere else except
 * radius 1, box_min and clip_min (-1, -1, -1), box_max and clip_max (1, 1, 1)
 * and normal (0, 1, 0). */
PRISM_API void prismDefaultObject(PrismObject* object, PrismObjectType type);
/* Adds an object; `out_object` (may be NULL) receives its index among the
 * scene's objects. */
PRISM_API PrismStatus prismAddObject(PrismScene scene, const PrismObject* object, uint32_t* out_object);
/* The colour of rays that leave the scene, and the ambient light (both: three
 * numbers in [0, 1e6]). */
PRISM_API PrismStatus prismSetBackground(PrismScene scene, const float color[3]);
PRISM_API PrismStatus prismSetAmbient(PrismScene scene, const float color[3]);

/* What a mesh file holds, for `prism info`: read with the plugins, not rendered. */
typedef struct PrismMeshReportImpl* PrismMeshReport;
typedef struct PrismMeshCounts {
  size_t struct_size;         /* sizeof(PrismMeshCounts); set by the caller */
  uint64_t vertices;
  uint64_t faces;             /* as written in the file */
  uint64_t triangles;         /* after triangulating polygons and expanding strips */
  uint64_t degenerate_triangles;
  uint32_t materials;
  uint32_t has_normals, has_texcoords, has_colors;
  float bounds_min[3], bounds_max[3]; /* both 0 for a mesh without vertices */
} PrismMeshCounts;
PRISM_API PrismStatus prismInspectMeshFile(const char* path, PrismMeshReport* out_report);
PRISM_API PrismStatus prismGetMeshCounts(PrismMeshReport report, PrismMeshCounts* counts);
/* The name of the plugin that read the file. */
PRISM_API const char* prismGetMeshPlugin(PrismMeshReport report);
/* Material `index` (< counts.materials): its name. */
PRISM_API const char* prismGetMeshMaterialName(PrismMeshReport report, uint32_t index);
PRISM_API uint32_t prismGetMeshWarningCount(PrismMeshReport report);
PRISM_API const char* prismGetMeshWarning(PrismMeshReport report, uint32_t index);
PRISM_API void prismReleaseMeshReport(PrismMeshReport report); /* NULL is a no-op */

/* Plugins found at start-up (PRISM_PLUGIN_PATH, then plugins/ next to libprism),
 * accepted or not, for `prism plugins`. */
typedef struct PrismPluginCandidateInfo {
  size_t struct_size;    /* sizeof(PrismPluginCandidateInfo); set by the caller */
  const char* path;
  const char* name;      /* "" when the library could not be read */
  const char* extensions; /* space-separated, e.g. "ply" */
  int accepted;
  const char* reason;    /* why it was refused; "" when accepted */
} PrismPluginCandidateInfo;
PRISM_API PrismStatus prismGetPluginCount(uint32_t* count);
/* Strings stay valid for the life of the process. */
PRISM_API PrismStatus prismGetPluginInfo(uint32_t index, PrismPluginCandidateInfo* info);

/* ---- rendering ----------------------------------------------------------------- */

/* Spatial index used for ray queries: a BVH (binned SAH), an adaptive octree, a
 * BSP (SAH kd-) tree, none (every ray against every primitive), or auto (the
 * default: none for scenes of at most 4 primitives, the BVH above). */
typedef enum PrismAccel {
  PRISM_ACCEL_BVH = 0,
  PRISM_ACCEL_OCTREE = 1,
  PRISM_ACCEL_BSP = 2,
  PRISM_ACCEL_NONE = 3,
  PRISM_ACCEL_AUTO = 4
} PrismAccel;

/* Parses "bvh", "octree", "bsp", "none" or "auto". */
PRISM_API PrismStatus prismParseAccel(const char* name, PrismAccel* accel);
/* The lower-case name of a structure ("bvh"), or NULL for an unknown value. */
PRISM_API const char* prismAccelName(PrismAccel accel);

/* Anti-aliasing: where primary rays pass through each pixel (docs/sampling.md).
 * AUTO: none at one sample per pixel, jitter above. */
typedef enum PrismAa {
  PRISM_AA_AUTO = 0,
  PRISM_AA_NONE = 1,     /* the pixel centre; spp must be 1 */
  PRISM_AA_GRID = 2,     /* n x n regular grid; spp = n^2 */
  PRISM_AA_QUINCUNX = 3, /* pixel corners shared with the neighbours, plus the centre; spp must be 1 */
  PRISM_AA_ADAPTIVE = 4, /* corners, subdivided where they differ by more than aa_threshold; spp must be 1 */
  PRISM_AA_JITTER = 5,   /* one uniform point in each of spp strata */
  PRISM_AA_POISSON = 6,  /* a Poisson-disk tile of spp points, randomly shifted per pixel */
  PRISM_AA_RANDOM = 7    /* spp independent uniform points */
} PrismAa;

/* Reconstruction filter of the per-pixel modes (radius in pixels): box 0.5, tent 1,
 * gaussian 1.5, mitchell 2. Quincunx always uses the tent, adaptive its area average. */
typedef enum PrismFilter {
  PRISM_FILTER_BOX = 0,
  PRISM_FILTER_TENT = 1,
  PRISM_FILTER_GAUSSIAN = 2,
  PRISM_FILTER_MITCHELL = 3
} PrismFilter;

/* How primary visibility is found: the first-hit Z-buffer pass, traced rays, or
 * AUTO (the Z-buffer whenever the camera allows it: no depth of field or motion blur). */
typedef enum PrismFirstHit {
  PRISM_FIRST_HIT_AUTO = 0,
  PRISM_FIRST_HIT_ZBUFFER = 1,
  PRISM_FIRST_HIT_TRACE = 2
} PrismFirstHit;

/* The point-in-polygon test of polygons that name none (docs/scene-format.md,
 * polygons): the crossing (Jordan curve) test, the radial (angle-sum) test, or
 * the left-right test (convex polygons only: a render with a non-convex one
 * fails with INVALID_ARGUMENT naming it). */
typedef enum PrismInsideTest {
  PRISM_INSIDE_CROSSING = 0,
  PRISM_INSIDE_RADIAL = 1,
  PRISM_INSIDE_LEFT_RIGHT = 2
} PrismInsideTest;

/* How point lights' shadow feelers find what is in the way: the acceleration
 * structure, the light buffer (a direction cube per point light whose cells
 * list the candidate occluders, docs/accel.md), or AUTO (the light buffer when
 * its cells list few candidates, else the structure). The same shadows either way. */
typedef enum PrismShadows {
  PRISM_SHADOWS_AUTO = 0,
  PRISM_SHADOWS_ACCEL = 1,
  PRISM_SHADOWS_LIGHTBUFFER = 2
} PrismShadows;

/* Bounding volumes: axis-aligned boxes, or "set of normals" slabs along four
 * diagonals too (Kay and Kajiya) around each analytic object in a structure's
 * leaves, tested before the object, and around each BVH child besides its box.
 * The same image either way. */
typedef enum PrismBounds { PRISM_BOUNDS_AABB = 0, PRISM_BOUNDS_KDOP = 1 } PrismBounds;

/* Parse a lower-case name ("auto", "none", "grid", "quincunx", "adaptive", "jitter",
 * "poisson", "random"; "box", "tent", "gaussian", "mitchell"; "auto", "zbuffer",
 * "trace"; "crossing", "radial", "left-right"; "auto", "accel", "lightbuffer";
 * "aabb", "kdop");
 * the Name functions return it, or NULL for an unknown value. */
PRISM_API PrismStatus prismParseAa(const char* name, PrismAa* aa);
PRISM_API const char* prismAaName(PrismAa aa);
PRISM_API PrismStatus prismParseFilter(const char* name, PrismFilter* filter);
PRISM_API const char* prismFilterName(PrismFilter filter);
PRISM_API PrismStatus prismParseFirstHit(const char* name, PrismFirstHit* first_hit);
PRISM_API const char* prismFirstHitName(PrismFirstHit first_hit);
PRISM_API PrismStatus prismParseInsideTest(const char* name, PrismInsideTest* inside_test);
PRISM_API const char* prismInsideTestName(PrismInsideTest inside_test);
PRISM_API PrismStatus prismParseShadows(const char* name, PrismShadows* shadows);
PRISM_API const char* prismShadowsName(PrismShadows shadows);
PRISM_API PrismStatus prismParseBounds(const char* name, PrismBounds* bounds);
PRISM_API const char* prismBoundsName(PrismBounds bounds);

typedef struct PrismRenderOptions {
  size_t struct_size;  /* sizeof(PrismRenderOptions); set by prismGetRenderOptions */
  uint32_t width;      /* film size in pixels */
  uint32_t height;
  uint32_t spp;        /* samples per pixel of grid, jitter, poisson, random; 1 for the other modes */
  uint32_t max_depth;  /* levels of reflected/refracted rays after the primary ray */
  float min_weight;    /* adaptive depth control: a ray whose weight falls under this is not traced */
  uint64_t seed;       /* seeds the sample positions (jitter, poisson, random) */
  uint32_t accel;      /* a PrismAccel */
  uint32_t aa;         /* a PrismAa */
  uint32_t filter;     /* a PrismFilter */
  uint32_t first_hit;  /* a PrismFirstHit */
  float aa_threshold;  /* adaptive: corner colours differing by more than this split a square (default 0.1) */
  uint32_t aa_max_level; /* adaptive: most subdivisions of a pixel's side, 0..8 (default 2) */
  uint32_t profile;    /* nonzero: time each kernel on the device (prismGetKernelTime); 0 by default */
  uint32_t inside_test; /* a PrismInsideTest: for polygons that name none */
  uint32_t shadows;     /* a PrismShadows: point lights' feelers */
  uint32_t bounds;      /* a PrismBounds: the BVH children's bounds */
  uint32_t check_nan;   /* nonzero: watch the film for NaN and infinity (prismGetNanReport); 0 by default */
} PrismRenderOptions;

/* Fills `options` with the scene's own settings (film and render blocks). */
PRISM_API PrismStatus prismGetRenderOptions(PrismScene scene, PrismRenderOptions* options);

typedef struct PrismRenderStats {
  size_t struct_size;          /* sizeof(PrismRenderStats); set by the caller */
  double seconds;              /* wall time of the render, kernels and transfers */
  double kernel_build_seconds; /* time spent building or loading kernels in this call */
  uint64_t primary_rays;
  uint64_t reflected_rays;
  uint64_t refracted_rays;
  uint64_t shadow_rays;
  uint32_t waves;              /* deepest wave reached + 1 */
  uint64_t rays_per_depth[32]; /* camera + secondary rays traced at each depth (0 = primary) */
  uint32_t accel;              /* the PrismAccel used (never PRISM_ACCEL_AUTO: what it chose) */
  double accel_build_seconds;  /* building the spatial index on the host */
  double rays_per_pixel;       /* primary samples / pixels (about 2 for quincunx, >= 1 for adaptive) */
  uint32_t first_hit_used;     /* PRISM_FIRST_HIT_ZBUFFER or PRISM_FIRST_HIT_TRACE */
  double setup_seconds;        /* of `seconds`, before the first sample: scene, structure, kernels, uploads */
  double trace_seconds;        /* the rest: tracing, accumulation, resolve, read-back */
  uint32_t shadows_used;       /* PRISM_SHADOWS_ACCEL or PRISM_SHADOWS_LIGHTBUFFER */
  double first_launch_seconds; /* of trace_seconds: kernels waiting on their first launch, where a driver
                                  compiles them for it (start-up cost; throughput is over the rest) */
} PrismRenderStats;

/* After a render with options->profile set: how many kernels ran, and kernel
 * `index`'s name (owned by the context, valid until its next render), its device
 * time summed over its launches, and the number of launches (longest first).
 * PRISM_ERROR_INVALID_OPERATION before such a render. */
PRISM_API PrismStatus prismGetKernelTimeCount(PrismContext context, uint32_t* count);
PRISM_API PrismStatus prismGetKernelTime(PrismContext context, uint32_t index, const char** name, double* seconds,
                                         uint64_t* launches);

/* After a render: each device's part of the frame (position as in
 * prismGetContextDeviceAt). A device that failed mid-frame (failed = 1, failure
 * says why; the string is owned by the context, valid until its next render) was
 * left out and its units traced again by the others; the image is the same. */
typedef struct PrismDeviceShare {
  size_t struct_size;     /* sizeof(PrismDeviceShare); set by the caller */
  uint64_t units;         /* units of the sample sequence it finished */
  uint64_t samples;       /* primary samples in them */
  double busy_seconds;    /* wall time it spent on them */
  uint32_t failed;
  const char* failure;
  const char* device;     /* its name; with frame parts, "part p: name" */
  uint64_t film_bytes;    /* device memory its film took at its largest: the whole
                             frame's on the device that resolves it, one unit's
                             on the others (absent from structs sized before it) */
} PrismDeviceShare;
/* How many devices took part: the context's, and at part 0 of a frame shared
 * by processes (prismSetFrameParts) every part's, part by part. */
PRISM_API PrismStatus prismGetRenderDeviceShareCount(PrismContext context, uint32_t* count);
PRISM_API PrismStatus prismGetRenderDeviceShare(PrismContext context, uint32_t position, PrismDeviceShare* share);
/* After a render: its warnings (a device that failed mid-frame; pixels of the
 * image that are not finite, with their count), one per index; owned by the
 * context, valid until its next render. */
PRISM_API PrismStatus prismGetRenderWarningCount(PrismContext context, uint32_t* count);
PRISM_API PrismStatus prismGetRenderWarning(PrismContext context, uint32_t index, const char** message);

/* After prismRender with options->check_nan set: the first contribution to the
 * film that was not finite (NaN or infinite), in render order (chunk by chunk of
 * the sample sequence, in a chunk depth by depth, lowest sample first), and the
 * ray that brought it. found is 0 when every contribution was finite.
 * PRISM_ERROR_INVALID_OPERATION unless the context's last prismRender had it. */
typedef struct PrismNanReport {
  size_t struct_size;      /* sizeof(PrismNanReport); set by the caller */
  uint32_t found;          /* 1: the fields below describe it */
  uint64_t sample;         /* the primary sample's index in the image's sample sequence */
  float film_x, film_y;    /* its film position: pixel (floor(film_x), floor(film_y)) */
  uint32_t ray_kind;       /* 0 primary, 1 reflected, 2 refracted, 3 shadow */
  uint32_t ray_depth;      /* 0 for the primary ray */
  float origin[3];
  float direction[3];
  int32_t primitive;       /* the primitive the ray hit, -1 for none or a shadow ray */
  float t;                 /* distance to that hit along the ray */
  float value[4];          /* the contribution: r, g, b and coverage */
} PrismNanReport;
PRISM_API PrismStatus prismGetNanReport(PrismContext context, PrismNanReport* report);

/* The checks prismRender makes of `options` before any work (sizes, samples,
 * depth, weights, sampling modes), with the same status and message: call it
 * before allocating the image, so a size over a limit is refused before a
 * caller sets gigabytes aside for it. Whether the film fits the device is
 * known only to prismRender (PRISM_ERROR_OUT_OF_MEMORY). */
PRISM_API PrismStatus prismCheckRenderOptions(const PrismRenderOptions* options);

/* Renders `scene` with `options` (NULL: the scene's own) into `rgba`, a caller-owned
 * buffer of width*height*4 floats, rows top to bottom, linear colour, alpha 1 on a hit
 * and 0 where the primary ray missed. `stats` may be NULL. */
PRISM_API PrismStatus prismRender(PrismContext context, PrismScene scene, const PrismRenderOptions* options,
                                  float* rgba, PrismRenderStats* stats);

typedef enum PrismAov {
  PRISM_AOV_DEPTH = 0,  /* 1 channel: distance along the unit primary ray, +inf on a miss */
  PRISM_AOV_NORMAL = 1, /* 3 channels: world-space unit normal facing the camera ray, 0 on a miss */
  PRISM_AOV_PRIMID = 2, /* 1 channel: index of the hit primitive (object), -1 on a miss */
  PRISM_AOV_ALBEDO = 3  /* 3 channels: diffuse colour (with texture) at the hit, 0 on a miss */
} PrismAov;

/* Channels of an AOV (1 or 3). */
PRISM_API PrismStatus prismGetAovChannels(PrismAov aov, uint32_t* channels);
/* Parses "depth", "normal", "primid" or "albedo". */
PRISM_API PrismStatus prismParseAov(const char* name, PrismAov* aov);
/* Copies an AOV of the context's last render into `out` (width*height*channels floats;
 * `count` is the buffer's size in floats). AOVs come from one sample of each pixel: the
 * centre (none, quincunx), the first sample (grid, jitter, poisson, random), or the
 * top-left corner (adaptive). */
PRISM_API PrismStatus prismGetAov(PrismContext context, PrismAov aov, float* out, size_t count);

/* One render's image, AOVs and statistics, owned by the result: it holds its
 * own copies, so it outlives the context and the scene that made it. */
typedef struct PrismResultImpl* PrismResult;
/* Renders like prismRender, into a new result (release it with
 * prismReleaseResult). Does not change what prismGetAov reads. */
PRISM_API PrismStatus prismRenderToResult(PrismContext context, PrismScene scene, const PrismRenderOptions* options,
                                          PrismResult* out_result);
PRISM_API PrismStatus prismGetResultSize(PrismResult result, uint32_t* width, uint32_t* height);
/* Pointers into the result (width*height*4 RGBA floats, or width*height*channels
 * for an AOV, rows top to bottom), valid until prismReleaseResult. */
PRISM_API PrismStatus prismGetResultImage(PrismResult result, const float** rgba);
PRISM_API PrismStatus prismGetResultAov(PrismResult result, PrismAov aov, const float** data, uint32_t* channels);
PRISM_API PrismStatus prismGetResultStats(PrismResult result, PrismRenderStats* stats);
/* The render's warnings, as prismGetRenderWarning gives a context's, owned by
 * the result and valid until prismReleaseResult. */
PRISM_API PrismStatus prismGetResultWarningCount(PrismResult result, uint32_t* count);
PRISM_API PrismStatus prismGetResultWarning(PrismResult result, uint32_t index, const char** message);
PRISM_API void prismReleaseResult(PrismResult result); /* NULL is a no-op */

/* ---- ray queries ------------------------------------------------------------------ */

/* prism as a ray-query engine for other programs: closest or any hit of caller
 * rays against a scene's primitives, numbered as the primid AOV numbers them
 * (the analytic objects in order, then the meshes' triangles, mesh by mesh, in
 * file order; docs/scene-format.md). The spatial index
 * is built on first use and kept in the context for the same scene and structure
 * until the scene changes. */
typedef struct PrismRay {
  float org[3];
  float tmin;
  float dir[3]; /* need not be unit length; t is in units of dir */
  float tmax;
} PrismRay;     /* 32 bytes: the record `prism trace` reads */

typedef struct PrismHit {
  float t;      /* +inf on a miss */
  int32_t prim; /* -1 on a miss */
  float u, v;   /* triangles: barycentrics of vertices 1 and 2; quadrics: u is 0 on the surface, 1 + 2 axis (+1 at max) on a cap; 0 otherwise */
} PrismHit;     /* 16 bytes: the record `prism trace` writes */

/* Closest hit in (tmin, tmax) for each of `count` rays. `trace_seconds` (may be
 * NULL) receives the time of the tracing alone, without build, upload or compile. */
PRISM_API PrismStatus prismIntersect(PrismContext context, PrismScene scene, PrismAccel accel, const PrismRay* rays,
                                     PrismHit* hits, size_t count, double* trace_seconds);
/* 1 where anything lies in (tmin, tmax) along the ray, else 0. */
PRISM_API PrismStatus prismOccluded(PrismContext context, PrismScene scene, PrismAccel accel, const PrismRay* rays,
                                    uint8_t* occluded, size_t count, double* trace_seconds);

/* ---- images -------------------------------------------------------------------- */

/* Writes linear float pixels (rows top to bottom, `channels` of 1, 3 or 4) to `path`
 * through OpenImageIO; the extension picks the format: .png (8-bit sRGB), .exr, .hdr,
 * .pfm (linear float), .tif. */
PRISM_API PrismStatus prismWriteImage(const char* path, const float* pixels, uint32_t width, uint32_t height,
                                      uint32_t channels);

#ifdef __cplusplus
}
#endif

#endif /* PRISM_H */
