/* The compact triangles of the meshes; shared by host and kernels.
 *
 * A mesh's triangles are not object records: each is three vertex indices
 * (12 bytes) into one float array of vertex positions, and its mesh has one
 * header record that says what the triangles share. Primitive ids
 * [triangle_base, triangle_base + triangle count) are these triangles, mesh by
 * mesh; the ids before them are object records (the analytic primitives).
 *
 * The object array on the device then holds, in order: the analytic
 * primitives [0, triangle_base), the mesh headers [triangle_base,
 * triangle_base + mesh count) sorted by first_triangle, and the motion and
 * data records (host/accel/scene_geometry.h). A header has an ObjectGpu's size
 * and its first four words, so a moving mesh's motion record is found as a
 * moving object's is (object_world_to_object).
 *
 * mesh_data, one float array: the positions of every mesh's vertices (xyz
 * each; indices count in vertices from the start), then per mesh as it needs
 * them: unit vertex normals (xyz per vertex), texture coordinates (uv per
 * vertex) and per-triangle materials (int bits). */
#ifndef PRISM_MESH_GPU_H
#define PRISM_MESH_GPU_H

#define OBJECT_MESH 102 /* the type of a mesh header: not a primitive */

typedef struct MeshGpu {
  int type;          /* OBJECT_MESH */
  int material;      /* every triangle's material, or -1: per triangle, at material_offset */
  int has_transform; /* 0 (world space) or OBJECT_MOVING (object space, moved per ray) */
  int flags;         /* OBJECT_FLAG_VERTEX_NORMALS, OBJECT_FLAG_TEXCOORDS; the motion record's offset when moving */
  int first_triangle; /* the primitive id of its first triangle */
  int first_vertex;   /* the index of its first vertex */
  int normal_offset;   /* mesh_data index of first_vertex's normal */
  int texcoord_offset; /* mesh_data index of first_vertex's uv */
  int material_offset; /* mesh_data index of first_triangle's material */
  int unused[19];
} MeshGpu;

#endif
