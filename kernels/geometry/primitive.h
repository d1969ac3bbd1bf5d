/* A primitive by its id, whichever way it is stored: an object record
 * (geometry/object.h) or a compact mesh triangle (shared/mesh_gpu.h). Every
 * query by primitive id goes through here: intersection, surface, material
 * and the world-to-object transform at a time.
 *
 * The kernels take the buffers as GEOMETRY_KERNEL_PARAMS and gather them into
 * a Geometry (GEOMETRY_INIT) that the functions below and the acceleration
 * structures share by pointer. */
#ifndef PRISM_GEOMETRY_PRIMITIVE_H
#define PRISM_GEOMETRY_PRIMITIVE_H

#include "common/math.h"
#include "geometry/object.h"
#include "shared/mesh_gpu.h"

typedef struct Geometry {
  __global const ObjectGpu* objects;
  __global const uint* triangles; /* 3 vertex indices per compact triangle */
  __global const float* mesh_data;
  int prim_count;    /* every primitive: object records and compact triangles */
  int triangle_base; /* the first compact triangle's id, and the first mesh header's index */
  int mesh_count;
} Geometry;

#define GEOMETRY_KERNEL_PARAMS                                                                                 \
  __global const ObjectGpu *geometry_objects, int geometry_prim_count, int geometry_triangle_base,           \
      int geometry_mesh_count, __global const uint *geometry_triangles, __global const float *geometry_mesh_data
#define GEOMETRY_INIT                                                                                        \
  {geometry_objects,   geometry_triangles,     geometry_mesh_data, geometry_prim_count, geometry_triangle_base, \
   geometry_mesh_count}

inline bool prim_is_compact(const Geometry* g, int id) { return id >= g->triangle_base; }

/* The header of a compact triangle's mesh: the last whose first triangle is at
 * or before id (a binary search over the headers; one compare for one mesh). */
inline __global const MeshGpu* prim_mesh(const Geometry* g, int id) {
  __global const MeshGpu* meshes = (__global const MeshGpu*)(g->objects + g->triangle_base);
  int lo = 0, hi = g->mesh_count - 1;
  while (lo < hi) {
    int mid = (lo + hi + 1) >> 1;
    if (meshes[mid].first_triangle <= id)
      lo = mid;
    else
      hi = mid - 1;
  }
  return meshes + lo;
}

/* A compact triangle's vertex indices and positions (object space when its mesh moves). */
inline uint3 prim_triangle_indices(const Geometry* g, int id) { return vload3(id - g->triangle_base, g->triangles); }
inline void prim_triangle_vertices(const Geometry* g, uint3 idx, float3* v0, float3* v1, float3* v2) {
  *v0 = vload3(idx.x, g->mesh_data);
  *v1 = vload3(idx.y, g->mesh_data);
  *v2 = vload3(idx.z, g->mesh_data);
}

/* Whether primitive id has a world-to-object transform, and then that
 * transform at `time` into m. */
inline bool prim_world_to_object(const Geometry* g, int id, float time, float* m) {
  __global const ObjectGpu* ob =
      prim_is_compact(g, id) ? (__global const ObjectGpu*)prim_mesh(g, id) : g->objects + id;
  if (!ob->has_transform) return false;
  object_world_to_object(ob, time, m);
  return true;
}

/* A compact triangle's mesh header, or NULL for a primitive with its own
 * record: looked up once by a caller that asks several things of one hit. */
inline __global const MeshGpu* prim_mesh_or_null(const Geometry* g, int id) {
  return prim_is_compact(g, id) ? prim_mesh(g, id) : 0;
}

/* mesh: prim_mesh_or_null(g, id). */
inline int prim_material_in(const Geometry* g, int id, __global const MeshGpu* mesh) {
  if (!mesh) return g->objects[id].material;
  return mesh->material >= 0 ? mesh->material
                             : as_int(g->mesh_data[mesh->material_offset + id - mesh->first_triangle]);
}

inline int prim_material(const Geometry* g, int id) { return prim_material_in(g, id, prim_mesh_or_null(g, id)); }

/* The ray (o, d) at `time` against primitive id; t is the ray's own parameter. */
inline bool prim_intersect(const Geometry* g, int id, float3 o, float3 d, float time, float tmin, float tmax,
                           float* t, float* u, float* v) {
  if (!prim_is_compact(g, id)) return object_intersect(g->objects + id, o, d, time, tmin, tmax, t, u, v);
#ifdef PRISM_MOTION
  float m[12];
  if (prim_world_to_object(g, id, time, m)) {
    o = xform_point(m, o);
    d = xform_vector(m, d);
  }
#endif
  float3 v0, v1, v2;
  prim_triangle_vertices(g, prim_triangle_indices(g, id), &v0, &v1, &v2);
  return triangle_intersect(o, d, tmin, tmax, v0, v1, v2, t, u, v);
}

/* Geometric unit normal and, when want_uv, texture coordinates at the hit (as
 * object_surface); a smooth mesh's normal is its vertex normals interpolated,
 * kept on the side of the winding's normal. mesh: prim_mesh_or_null(g, id),
 * which a caller that also wants the material looks up once for both. */
inline void prim_surface(const Geometry* g, int id, __global const MeshGpu* mesh, float time, HitGpu hit,
                            bool want_uv, float3 o, float3 d, float3* normal, float2* uv) {
  if (!mesh) {
    object_surface(g->objects + id, o, d, time, hit, want_uv, normal, uv);
    return;
  }
  uint3 idx = prim_triangle_indices(g, id);
  float3 v0, v1, v2;
  prim_triangle_vertices(g, idx, &v0, &v1, &v2);
  float3 n = triangle_normal(v0, v1, v2);
  float w0 = 1.0f - hit.u - hit.v;
  *uv = (float2)(hit.u, hit.v);
  if (mesh->flags & OBJECT_FLAG_TEXCOORDS) {
    __global const float* tc = g->mesh_data + mesh->texcoord_offset;
    uint3 k = idx - (uint3)(mesh->first_vertex);
    *uv = w0 * vload2(k.x, tc) + hit.u * vload2(k.y, tc) + hit.v * vload2(k.z, tc);
  }
  if (mesh->flags & OBJECT_FLAG_VERTEX_NORMALS) {
    __global const float* vn = g->mesh_data + mesh->normal_offset;
    uint3 k = idx - (uint3)(mesh->first_vertex);
    float3 smooth = w0 * vload3(k.x, vn) + hit.u * vload3(k.y, vn) + hit.v * vload3(k.z, vn);
    float len = sb_length(smooth);
    if (len > 0.0f) n = sb_dot(smooth, n) < 0.0f ? -smooth / len : smooth / len;
  }
#ifdef PRISM_MOTION
  float m[12];
  if (mesh->has_transform) {
    object_world_to_object((__global const ObjectGpu*)mesh, time, m);
    n = sb_normalize(xform_normal(m, n));
  }
#endif
  *normal = n;
}

#endif
