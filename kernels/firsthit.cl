/* firsthit: the first-hit (Z-buffer) pass for a pinhole camera. For each sample
 * position it finds the nearest primitive along the sample's primary ray, testing
 * only the candidates binned on the host into the sample's screen tile
 * (host/render/firsthit.cpp) plus the unbounded ones every tile shares (planes,
 * primitives crossing the camera plane). The test is the tracer's own
 * object_intersect, so depth and id are what tracing the ray gives; equal depths go
 * to the lower primitive index, as in a brute-force loop over the scene. */
#include "geometry/object.h"
#include "sampling/camera_ray.h"

inline void firsthit_test(__global const ObjectGpu* objects, int prim, float3 o, float3 d, HitGpu* hit) {
  /* A lower index may also take an equal t: allow t up to the next float. */
  float tmax = prim < hit->prim || hit->prim < 0 ? nextafter(hit->t, PRISM_INF) : hit->t;
  float t, u, v;
  if (object_intersect(&objects[prim], o, d, 0.0f, tmax, &t, &u, &v)) {
    hit->t = t;
    hit->prim = prim;
    hit->u = u;
    hit->v = v;
  }
}

__kernel void firsthit(__global const CameraGpu* camera, __global const ObjectGpu* objects, int tile_size,
                       int tiles_x, int tiles_y, __global const int* tile_start, __global const int* tile_prims,
                       __global const int* global_prims, int global_count, __global const float* xy, int count,
                       __global HitGpu* hits) {
  int k = get_global_id(0);
  if (k >= count) return;
  float x = xy[2 * k], y = xy[2 * k + 1];
  int tx = clamp((int)floor(x / (float)tile_size), 0, tiles_x - 1);
  int ty = clamp((int)floor(y / (float)tile_size), 0, tiles_y - 1);
  int tile = ty * tiles_x + tx;
  float3 o = load3g(camera->origin);
  float3 d = camera_ray_dir(camera, x, y);

  HitGpu hit;
  hit.t = PRISM_INF;
  hit.prim = -1;
  hit.u = 0.0f;
  hit.v = 0.0f;
  for (int n = tile_start[tile]; n < tile_start[tile + 1]; ++n) firsthit_test(objects, tile_prims[n], o, d, &hit);
  for (int n = 0; n < global_count; ++n) firsthit_test(objects, global_prims[n], o, d, &hit);
  hits[k] = hit;
}
