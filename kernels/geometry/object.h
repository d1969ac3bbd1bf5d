/* Intersection and surface queries for any ObjectGpu, dispatching on its type:
 * the kernels' registration of the primitive kinds (each kind's routines are in
 * its own geometry/<kind>.h; its host half in host/scene/primitives/).
 * Transformed spheres and boxes are intersected in object space: the ray is
 * mapped by the world-to-object matrix without renormalising, so t is the same
 * parameter in both spaces. */
#ifndef PRISM_GEOMETRY_OBJECT_H
#define PRISM_GEOMETRY_OBJECT_H

#include "common/math.h"
#include "shared/hit_gpu.h"
#include "shared/object_gpu.h"

/* The kinds compiled in, bit k for OBJECT_k. The host passes the scene's
 * (-DPRISM_KINDS, host: primitiveKernelOptions), so the programs of a scene without
 * quadrics, polygons, polyhedra or patches leave their code out: PoCL's build
 * time grows with the code, and a cold start pays it. Spheres, boxes, planes
 * and triangles are small and always in; without the option, every kind is. */
#ifndef PRISM_KINDS
#define PRISM_KINDS 0xff
#endif
#define PRISM_HAS_KIND(kind) ((PRISM_KINDS >> (kind)) & 1)

#include "geometry/box.h"
#include "geometry/motion.h"
#include "geometry/plane.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#if PRISM_HAS_KIND(OBJECT_PATCH)
#include "geometry/patch.h"
#endif
#if PRISM_HAS_KIND(OBJECT_POLYGON)
#include "geometry/polygon.h"
#endif
#if PRISM_HAS_KIND(OBJECT_POLYHEDRON)
#include "geometry/polyhedron.h"
#endif
#if PRISM_HAS_KIND(OBJECT_QUADRIC)
#include "geometry/quadric.h"
#endif

inline float3 xform_vector(const float* m, float3 v) {
  return (float3)(m[0] * v.x + m[1] * v.y + m[2] * v.z, m[4] * v.x + m[5] * v.y + m[6] * v.z,
                  m[8] * v.x + m[9] * v.y + m[10] * v.z);
}
inline float3 xform_point(const float* m, float3 p) { return xform_vector(m, p) + (float3)(m[3], m[7], m[11]); }
/* Object-space normal to world space: the transpose of the world-to-object
 * linear part is the inverse transpose of object-to-world. */
inline float3 xform_normal(const float* m, float3 n) {
  return (float3)(m[0] * n.x + m[4] * n.y + m[8] * n.z, m[1] * n.x + m[5] * n.y + m[9] * n.z,
                  m[2] * n.x + m[6] * n.y + m[10] * n.z);
}

/* The side data of a kind that keeps some (kernels/shared/object_gpu.h). Its
 * floats run on past the record into the records after it, so the pointer is
 * made from an integer address: a cast record pointer would be folded by the
 * compiler into an index of a member array (p[12]), which then overruns it as
 * far as a bounds checker (Oclgrind) can tell. */
inline __global const float* object_side_data(__global const ObjectGpu* ob) {
  uintptr_t record = (uintptr_t)(ob + as_int(ob->p[OBJECT_DATA_WORD]));
  return (__global const float*)(record + OBJECT_DATA_HEADER_FLOATS * sizeof(float));
}

/* The world-to-object matrix of a transformed object at `time`, into m. */
inline void object_world_to_object(__global const ObjectGpu* ob, float time, float* m) {
#ifdef PRISM_MOTION /* built only for scenes with moving objects (host: kMotionKernelOption) */
  if (ob->has_transform == OBJECT_MOVING) {
    motion_world_to_object((__global const MotionGpu*)(ob + (ob->flags >> OBJECT_MOTION_SHIFT)), time, m);
    return;
  }
#endif
  for (int i = 0; i < 12; ++i) m[i] = ob->world_to_object[i];
}

/* The ray (o, d) at `time` against one object; t is the ray's own parameter. */
inline bool object_intersect(__global const ObjectGpu* ob, float3 o, float3 d, float time, float tmin, float tmax,
                             float* t, float* u, float* v) {
  if (ob->has_transform) {
    float m[12];
    object_world_to_object(ob, time, m);
    o = xform_point(m, o);
    d = xform_vector(m, d);
  }
  __global const float* p = ob->p;
  *u = 0.0f;
  *v = 0.0f;
  switch (ob->type) {
    case OBJECT_SPHERE:
      return sphere_intersect(o, d, tmin, tmax, load3g(p), p[3], t);
    case OBJECT_BOX:
      return box_intersect(o, d, tmin, tmax, load3g(p), load3g(p + 3), t);
    case OBJECT_PLANE:
      return plane_intersect(o, d, tmin, tmax, load3g(p), load3g(p + 3), t);
    case OBJECT_TRIANGLE:
      return triangle_intersect(o, d, tmin, tmax, load3g(p), load3g(p + 3), load3g(p + 6), t, u, v);
#if PRISM_HAS_KIND(OBJECT_QUADRIC)
    case OBJECT_QUADRIC: { /* u carries the surface hit (QUADRIC_SURFACE or a cap) to object_surface */
      int face;
      bool hit = quadric_intersect(o, d, tmin, tmax, p, object_side_data(ob), (ob->flags & OBJECT_FLAG_CAPPED) != 0,
                                   t, &face);
      *u = (float)face;
      return hit;
    }
#endif
#if PRISM_HAS_KIND(OBJECT_POLYGON)
    case OBJECT_POLYGON:
      return polygon_intersect(o, d, tmin, tmax, p, object_side_data(ob), t);
#endif
#if PRISM_HAS_KIND(OBJECT_POLYHEDRON)
    case OBJECT_POLYHEDRON: { /* u carries the plane hit to object_surface */
      int face;
      bool hit = polyhedron_intersect(o, d, tmin, tmax, (int)p[0], object_side_data(ob), t, &face);
      *u = (float)face;
      return hit;
    }
#endif
#if PRISM_HAS_KIND(OBJECT_PATCH)
    case OBJECT_PATCH:
      return patch_intersect(o, d, tmin, tmax, p, object_side_data(ob), t, u, v);
#endif
  }
  return false;
}

/* Geometric unit normal (outward for closed objects) and, when want_uv (a
 * textured material), texture coordinates at the hit of ray (o, d); *uv is left
 * as it is otherwise. */
inline void object_surface(__global const ObjectGpu* ob, float3 o, float3 d, float time, HitGpu hit, bool want_uv,
                           float3* normal, float2* uv) {
  float m[12];
  if (ob->has_transform) {
    object_world_to_object(ob, time, m);
    o = xform_point(m, o);
    d = xform_vector(m, d);
  }
  float3 p = o + hit.t * d;
  __global const float* q = ob->p;
  float3 n;
  switch (ob->type) {
    case OBJECT_SPHERE:
      n = sphere_normal(p, load3g(q));
      if (want_uv) *uv = sphere_uv(n); /* two inverse trigonometric functions */
      break;
    case OBJECT_BOX:
      n = box_normal(p, load3g(q), load3g(q + 3));
      if (want_uv) *uv = box_uv(p, n);
      break;
    case OBJECT_PLANE:
      n = load3g(q + 3);
      if (want_uv) *uv = plane_uv(p, load3g(q), n);
      break;
#if PRISM_HAS_KIND(OBJECT_QUADRIC)
    case OBJECT_QUADRIC: {
      int face = (int)hit.u;
      n = quadric_normal(q, p, face);
      if (want_uv) *uv = quadric_uv(p, object_side_data(ob), face);
      break;
    }
#endif
#if PRISM_HAS_KIND(OBJECT_POLYGON)
    case OBJECT_POLYGON:
      n = load3g(q);
      if (want_uv) *uv = polygon_uv(q, p);
      break;
#endif
#if PRISM_HAS_KIND(OBJECT_POLYHEDRON)
    case OBJECT_POLYHEDRON:
      n = load3g(object_side_data(ob) + 4 * (int)hit.u);
      if (want_uv) *uv = polyhedron_uv(p, n);
      break;
#endif
#if PRISM_HAS_KIND(OBJECT_PATCH)
    case OBJECT_PATCH:
      n = patch_normal(object_side_data(ob), hit.u, hit.v);
      if (want_uv) *uv = patch_uv(q, hit.u, hit.v);
      break;
#endif
    default: /* a triangle record (a mesh's triangles are compact: geometry/primitive.h) */
      n = triangle_normal(load3g(q), load3g(q + 3), load3g(q + 6));
      *uv = (float2)(hit.u, hit.v);
      break;
  }
  *normal = ob->has_transform ? sb_normalize(xform_normal(m, n)) : n;
}

#endif
