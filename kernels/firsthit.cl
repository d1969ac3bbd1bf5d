/* firsthit: the first-hit (Z-buffer) pass for a pinhole camera. For each sample
 * position it finds the nearest primitive along the sample's primary ray, testing
 * only the candidates binned on the host into the sample's screen tile
 * (host/render/firsthit.cpp) plus the unbounded ones every tile shares (planes,
 * primitives crossing the camera plane), after cheap tests of the sample against
 * the candidate's padded screen bounds and depth bound. The ray test is the tracer's own
 * object_intersect, so depth and id are what tracing the ray gives; equal depths go
 * to the lower primitive index, as in a brute-force loop over the scene. */
#include "geometry/object.h"
#include "sampling/camera_ray.h"

/* time: the shutter's open, the one instant of the rays this pass serves. */
inline void firsthit_test(__global const ObjectGpu* objects, int prim, float3 o, float3 d, float time, HitGpu* hit) {
  /* A lower index may also take an equal t: allow t up to the next float. */
  float tmax = prim < hit->prim || hit->prim < 0 ? nextafter(hit->t, PRISM_INF) : hit->t;
  float t, u, v;
  if (object_intersect(&objects[prim], o, d, time, 0.0f, tmax, &t, &u, &v)) {
    hit->t = t;
    hit->prim = prim;
    hit->u = u;
    hit->v = v;
  }
}

__kernel void firsthit(__global const CameraGpu* camera, __global const ObjectGpu* objects, int tile_size,
                       int tiles_x, int tiles_y, __global const int* tile_start, __global const int* tile_prims,
                       __global const float* tile_bounds, __global const float* tile_depths,
                       __global const int* global_prims, int global_count,
                       __global const float* xy, int count, __global HitGpu* hits) {
  int k = get_global_id(0);
  if (k >= count) return;
  float x = xy[2 * k], y = xy[2 * k + 1];
  int tx = clamp((int)floor(x / (float)tile_size), 0, tiles_x - 1);
  int ty = clamp((int)floor(y / (float)tile_size), 0, tiles_y - 1);
  int tile = ty * tiles_x + tx;
  float3 o = load3g(camera->origin);
  float3 d = camera_ray_dir(camera, x, y);
  float time = camera->shutter_open;

  HitGpu hit;
  hit.t = PRISM_INF;
  hit.prim = -1;
  hit.u = 0.0f;
  hit.v = 0.0f;
  /* The unbounded candidates first: a near hit among them lets the depth test
   * below skip tile candidates behind it. */
  for (int n = 0; n < global_count; ++n) firsthit_test(objects, global_prims[n], o, d, time, &hit);
  /* A hit at t lies at view depth t * cos(angle to the forward axis). */
  float cos_forward = dot(d, load3g(camera->forward));
  for (int n = tile_start[tile]; n < tile_start[tile + 1]; ++n) {
    /* The candidate's padded screen bounds: a sample outside them cannot see it
     * (the pad, 0.1 pixel, is far more than the ray's float error). */
    float4 b = vload4(n, tile_bounds);
    if (x < b.x || y < b.y || x > b.z || y > b.w) continue;
    /* Nor can a candidate wholly behind the hit found so far (its depth bound is
     * 1e-4 nearer than the hull, far more than float error, so ties still get tested). */
    if (tile_depths[n] > hit.t * cos_forward) continue;
    firsthit_test(objects, tile_prims[n], o, d, time, &hit);
  }
  hits[k] = hit;
}
