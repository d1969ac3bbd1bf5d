/* prism_plugin.h -- the C ABI between prism and its mesh-format plugins.
 *
 * A plugin is a shared library that exports exactly one symbol,
 * prism_plugin_entry_v1, returning a static description of itself. The host
 * (libprism) calls its load function with a table of callbacks (the sink)
 * through which the plugin pushes vertices, faces and materials. All memory is
 * owned by whoever allocated it: the plugin never frees host memory and the
 * host never frees plugin memory, so a plugin may be built with any C or C++
 * toolchain and any C++ standard library.
 *
 * Versioning: the major ABI version is part of the entry symbol's name, so a
 * plugin built for another major version is simply not found ("missing
 * symbol"), and it is repeated in PrismPluginInfo.abi_version as a second
 * check. Within one major version, structs only ever grow at the end; each
 * starts with struct_size so the reader can tell which fields exist.
 *
 * This header is C99 and includes only <stddef.h> and <stdint.h>.
 * docs/plugins.md walks through writing a plugin (plugins/example/).
 */
#ifndef PRISM_PLUGIN_H
#define PRISM_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The ABI major version this header describes. */
#define PRISM_PLUGIN_ABI_VERSION 1

/* Marks the entry point for export when the plugin is built with
 * -fvisibility=hidden (recommended: nothing else should be exported). */
#if defined(_WIN32)
#define PRISM_PLUGIN_EXPORT __declspec(dllexport)
#elif defined(__GNUC__)
#define PRISM_PLUGIN_EXPORT __attribute__((visibility("default")))
#else
#define PRISM_PLUGIN_EXPORT
#endif

/* Status codes returned by PrismPluginInfo.load. */
typedef enum PrismPluginStatus {
  PRISM_PLUGIN_OK = 0,
  PRISM_PLUGIN_ERROR_IO = 1,          /* the file could not be opened or read */
  PRISM_PLUGIN_ERROR_PARSE = 2,       /* the file is malformed (err has the line) */
  PRISM_PLUGIN_ERROR_UNSUPPORTED = 3, /* well-formed, but a variant this plugin does not read */
  PRISM_PLUGIN_ERROR_LIMIT = 4,       /* counts or sizes beyond what the plugin accepts */
  PRISM_PLUGIN_ERROR_OUT_OF_MEMORY = 5,
  PRISM_PLUGIN_ERROR_SINK = 6,        /* a sink callback returned non-zero: stop at once */
  PRISM_PLUGIN_ERROR_INTERNAL = 7     /* anything else (an unexpected exception) */
} PrismPluginStatus;

/* Filled by the plugin when load fails. The host owns it and zeroes it before
 * the call. message is always NUL-terminated by the plugin (truncate if
 * needed); it should say what is wrong, not which file (the host adds that). */
typedef struct PrismPluginError {
  char message[512];
  uint64_t line;   /* 1-based line in the file where the problem is; 0 = unknown or binary */
  uint64_t offset; /* byte offset in the file, for binary data; 0 = unknown */
} PrismPluginError;

/* One material as a Wavefront MTL file (or any format) describes it. The
 * host maps these fields to its own shading model (docs/plugins.md lists the
 * mapping). Pointers are only valid during the add_material call: the host
 * copies what it keeps. */
typedef struct PrismMaterialDesc {
  uint32_t struct_size; /* sizeof(PrismMaterialDesc) as the plugin knows it */
  uint32_t reserved0;   /* set to 0; keeps the floats 8-byte aligned */
  const char* name;     /* material name (UTF-8), never NULL; may be "" */
  float kd[3];          /* Kd: diffuse colour, 0..1 */
  float ka[3];          /* Ka: ambient colour, 0..1 */
  float ks[3];          /* Ks: specular colour, 0..1 */
  float ns;             /* Ns: specular exponent (shininess) */
  float ni;             /* Ni: index of refraction (1 = none) */
  float d;              /* d: dissolve, 1 = opaque, 0 = fully transparent (Tr = 1 - d) */
  int32_t illum;        /* illum: MTL illumination model 0..10, or -1 when not given */
  uint32_t reserved1;   /* set to 0 */
  const char* map_kd;   /* map_Kd: diffuse texture path as written (relative to
                           the mesh file's folder when not absolute), or NULL */
} PrismMaterialDesc;

/* The host's callbacks. Every callback gets `host` back as its first
 * argument, returns 0 to continue and non-zero to ask the plugin to stop
 * (the host keeps its own reason); the plugin must then return
 * PRISM_PLUGIN_ERROR_SINK promptly without further callbacks.
 *
 * Order of calls: begin once, first; then any interleaving of the others.
 * Per-vertex attributes (normal, texcoord, colour) are numbered by call order
 * like positions: either no call of a kind or exactly one per vertex. */
typedef struct PrismMeshSink {
  uint32_t struct_size; /* sizeof(PrismMeshSink) as the host knows it */
  uint32_t reserved0;
  void* host;           /* opaque host state: pass it back, never touch it */

  /* Size hints, from the file's header when it has one (0 = unknown). Only
   * advisory: the host never trusts them for more than pre-allocation. */
  int (*begin)(void* host, uint64_t vertex_count_hint, uint64_t face_count_hint);

  /* Appends vertex number <vertices so far>: its position. */
  int (*add_position)(void* host, float x, float y, float z);
  /* Appends the next vertex normal (need not be unit length). */
  int (*add_normal)(void* host, float x, float y, float z);
  /* Appends the next vertex texture coordinate. */
  int (*add_texcoord)(void* host, float u, float v);
  /* Appends the next vertex colour, linear 0..1 (convert 0..255 integers). */
  int (*add_color)(void* host, float r, float g, float b);

  /* Appends one polygon (3 or more corners, 0-based vertex indices, in the
   * file's winding order). material is an index into the materials added so
   * far or still to come, or -1 for "the object's own material". The host
   * splits polygons into triangles as a fan (v0, vk, vk+1) and checks every
   * index once loading has finished. */
  int (*add_face)(void* host, const uint32_t* indices, uint32_t corner_count, int32_t material);

  /* Appends material number <materials so far>. */
  int (*add_material)(void* host, const PrismMaterialDesc* material);

  /* A non-fatal problem worth telling the user (missing MTL file, dropped
   * attribute...). line is 1-based or 0. The message is copied. */
  int (*warning)(void* host, const char* message, uint64_t line);
} PrismMeshSink;

/* Reads the mesh file at path (UTF-8, as the user gave it) into the sink.
 * Must not throw or longjmp across this boundary, must not abort the process,
 * must not keep pointers into the sink after returning, and must return in
 * time bounded by the file's size (no endless loops on malformed input).
 * Returns PRISM_PLUGIN_OK or a PrismPluginStatus with err filled in. */
typedef int (*PrismPluginLoadFn)(const char* path, const PrismMeshSink* sink, PrismPluginError* err);

/* The plugin's description. Returned by the entry point; must stay valid
 * (static storage) for as long as the library is loaded. */
typedef struct PrismPluginInfo {
  uint32_t struct_size;  /* sizeof(PrismPluginInfo) as the plugin knows it */
  uint32_t abi_version;  /* PRISM_PLUGIN_ABI_VERSION the plugin was built with */
  const char* name;      /* short unique name, e.g. "ply" (ASCII, no spaces) */
  const char* const* extensions; /* NULL-terminated list of file extensions
                                    it reads, without the dot, e.g. {"ply", NULL};
                                    matched case-insensitively */
  const char* description; /* one line for `prism plugins`, e.g. "PLY ascii and binary" */
  PrismPluginLoadFn load;  /* never NULL */
  /* Optional (may be NULL): for files without an extension, the host passes
   * the file's first bytes (at most 4096) and uses the first plugin whose
   * probe returns non-zero. Must only look at those bytes. */
  int (*probe)(const unsigned char* head, size_t size);
} PrismPluginInfo;

/* The one symbol a plugin exports. Its name carries the ABI major version. */
typedef const PrismPluginInfo* (*PrismPluginEntryFn)(void);
#define PRISM_PLUGIN_ENTRY_SYMBOL "prism_plugin_entry_v1"
PRISM_PLUGIN_EXPORT const PrismPluginInfo* prism_plugin_entry_v1(void);

#ifdef __cplusplus
}
#endif

#endif /* PRISM_PLUGIN_H */
