/* Reading and writing RayGpu fields as vectors. */
#ifndef PRISM_SHADING_RAY_IO_H
#define PRISM_SHADING_RAY_IO_H

#include "shared/ray_gpu.h"

inline float3 ray_origin(RayGpu r) { return (float3)(r.ox, r.oy, r.oz); }
inline float3 ray_dir(RayGpu r) { return (float3)(r.dx, r.dy, r.dz); }
inline float3 ray_weight(RayGpu r) { return (float3)(r.wr, r.wg, r.wb); }

inline RayGpu ray_make(float3 o, float3 d, float tmin, float tmax, float3 w, int pixel, int depth, int kind,
                       int sample) {
  RayGpu r;
  r.ox = o.x;
  r.oy = o.y;
  r.oz = o.z;
  r.tmin = tmin;
  r.dx = d.x;
  r.dy = d.y;
  r.dz = d.z;
  r.tmax = tmax;
  r.wr = w.x;
  r.wg = w.y;
  r.wb = w.z;
  r.pixel = pixel;
  r.depth = depth;
  r.kind = kind;
  r.sample = sample;
  r.aov_pixel = -1;
  r.time = 0.0f;
  r.dim = 0;
  r.strata_id = 0;
  r.pad = 0;
  return r;
}

/* A ray spawned at a parent's hit: the same film key, sample, instant and strata,
 * its own next sample dimension. */
inline RayGpu ray_child(RayGpu parent, float3 o, float3 d, float tmax, float3 w, int depth, int kind, int dim) {
  RayGpu r = ray_make(o, d, 0.0f, tmax, w, parent.pixel, depth, kind, parent.sample);
  r.time = parent.time;
  r.dim = dim;
  r.strata_id = parent.strata_id;
  return r;
}

#endif
