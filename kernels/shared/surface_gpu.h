/* A shaded hit, kept by shade for spawn_shadows: what a shadow feeler needs to
 * know of the point it leaves. Shared by host (which sizes its buffer) and
 * kernels. */
#ifndef PRISM_SURFACE_GPU_H
#define PRISM_SURFACE_GPU_H

typedef struct SurfaceGpu {
  float p[4];      /* the hit point moved just off the surface, on the viewer's side; w: the ray's time */
  float n[4];      /* unit normal on the viewer's side */
  float v[4];      /* unit direction to the viewer */
  float kd[4];     /* diffuse colour with its texture */
  float weight[4]; /* the ray's weight */
  int material;    /* -1: no surface (a miss, or an area light was hit): no feelers */
  int pixel, sample, strata_id, dim, depth;
  int pad[2];
} SurfaceGpu;

#endif
