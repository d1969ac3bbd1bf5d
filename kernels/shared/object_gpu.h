/* One primitive as the kernels see it; shared by host and kernels. Each kind
 * lays out p[] its own way (host/scene/primitives/<kind>.cpp and
 * kernels/geometry/<kind>.h). */
#ifndef PRISM_OBJECT_GPU_H
#define PRISM_OBJECT_GPU_H

#define OBJECT_SPHERE 0
#define OBJECT_BOX 1
#define OBJECT_PLANE 2
#define OBJECT_TRIANGLE 3
#define OBJECT_QUADRIC 4
#define OBJECT_POLYGON 5
#define OBJECT_POLYHEDRON 6
#define OBJECT_PATCH 7

/* A polygon's point-in-polygon test (geometry/polygon.h). */
#define POLYGON_CROSSING 0
#define POLYGON_RADIAL 1
#define POLYGON_LEFT_RIGHT 2

/* A mesh (shared/mesh_gpu.h) with unit vertex normals to interpolate. */
#define OBJECT_FLAG_VERTEX_NORMALS 1
/* A quadric closed by its clip box's faces (geometry/quadric.h). */
#define OBJECT_FLAG_CAPPED 2
/* A mesh with texture coordinates at its vertices. */
#define OBJECT_FLAG_TEXCOORDS 4

/* has_transform values. A moving object keeps its geometry (and vertex normals)
 * in object space; its world-to-object matrix is made per ray, at the ray's
 * time, from the motion record `flags >> OBJECT_MOTION_SHIFT` entries further on
 * in the same array (kernels/shared/motion_gpu.h). */
#define OBJECT_STATIC 1
#define OBJECT_MOVING 2
#define OBJECT_MOTION_SHIFT 8

/* Side data. A kind whose parameters do not fit p[] keeps them in a data
 * record (ObjectDataGpu) after every primitive in the same array, and the
 * record's offset from the primitive, in records, as the int bits of
 * p[OBJECT_DATA_WORD]. The record's floats start at its `words` and run on
 * through as many following records as they need (those carry no header). */
#define OBJECT_DATA 101 /* the type of a data record: not a primitive */
#define OBJECT_DATA_HEADER_FLOATS 4 /* the floats start this far into the record */
#define OBJECT_DATA_WORD 11

typedef struct ObjectGpu {
  int type;     /* OBJECT_* */
  int material; /* index into the material array */
  int has_transform; /* 0: none; OBJECT_STATIC: intersect in object space through `world_to_object`; OBJECT_MOVING */
  int flags;    /* OBJECT_FLAG_* and, when moving, the motion record's offset; aligns the arrays */
  /* sphere: center xyz, radius; box: min xyz, max xyz; plane: point xyz, normal xyz;
   * triangle (a triangle object; a mesh's triangles are compact, shared/mesh_gpu.h):
   * v0 xyz, v1 xyz, v2 xyz (world space); quadric: coefficients A..J
   * (scaled to a largest magnitude of 1), its clip box in side data; polygon:
   * unit normal xyz, plane offset, the two axes it is projected on, vertex
   * count, inside test (POLYGON_*), orientation (+1 or -1) in the projection;
   * its vertices (xyz each) in side data; polyhedron: the plane count, its planes
   * (unit normal xyz, offset each) and then its box (min xyz, max xyz) in side
   * data; patch (a piece of a bicubic patch): the piece's u0, u1, v0, v1 in its
   * patch, its box (min xyz, max xyz), Newton's tolerance, its 16 control
   * points (xyz each, i along u, then j along v) in side data. */
  float p[12];
  /* Rows of the 3x4 world-to-object affine matrix. Object-space normals map back
   * with its transposed linear part. */
  float world_to_object[12];
} ObjectGpu;

typedef struct ObjectDataGpu {
  int type;  /* OBJECT_DATA */
  int size;  /* floats, from `words` on */
  int unused[2];
  float words[24];
} ObjectDataGpu;

#endif
