/* Primary rays from film positions (x in [0, W], y in [0, H], pixel (i, j)
 * covering [i, i+1] x [j, j+1], y down). camera_ray_dir is the pinhole at
 * shutter open, the arithmetic the first-hit pass shares with generate, so a
 * sample traced either way meets the same hit; camera_ray adds the time, the
 * moving camera and the thin lens. */
#ifndef PRISM_SAMPLING_CAMERA_RAY_H
#define PRISM_SAMPLING_CAMERA_RAY_H

#include "common/math.h"
#include "sampling/warp.h"
#include "shared/camera_gpu.h"

inline float3 camera_ray_dir(__global const CameraGpu* camera, float fx, float fy) {
  float x = 2.0f * fx / (float)camera->width - 1.0f;
  float y = 1.0f - 2.0f * fy / (float)camera->height;
  return sb_normalize(load3g(camera->forward) + x * load3g(camera->right) + y * load3g(camera->up));
}

/* camera_ray_dir of eight film positions, lane by lane the same operations in
 * the same order (division and sqrt round correctly in vector lanes as in
 * scalars, so the same bits); false, and nothing written, when a lane's
 * squared length needs sb_normalize's scaling. */
inline bool camera_ray_dir8(__global const CameraGpu* camera, float8 fx, float8 fy, float8* dx, float8* dy, float8* dz) {
  float8 x = 2.0f * fx / (float)camera->width - 1.0f;
  float8 y = 1.0f - 2.0f * fy / (float)camera->height;
  float3 f = load3g(camera->forward), r = load3g(camera->right), u = load3g(camera->up);
  float8 vx = f.x + x * r.x + y * u.x, vy = f.y + x * r.y + y * u.y, vz = f.z + x * r.z + y * u.z;
  float8 d = vx * vx + vy * vy + vz * vz;
  if (any8_t(!(d > 0x1p-100f && d < 0x1p100f))) return false;
  float8 len = sqrt(d);
  *dx = vx / len;
  *dy = vy / len;
  *dz = vz / len;
  return true;
}

/* The ray of film position (fx, fy) for time sample u_time and lens sample
 * u_lens (both in [0, 1)): origin *o, unit direction *d, instant *time. */
inline void camera_ray(__global const CameraGpu* camera, float fx, float fy, float u_time, float2 u_lens, float3* o,
                       float3* d, float* time) {
  float open = camera->shutter_open, close = camera->shutter_close;
  *time = close > open ? open + u_time * (close - open) : open;
  float3 origin = load3g(camera->origin);
  float3 forward = load3g(camera->forward);
  float3 right = load3g(camera->right), up = load3g(camera->up);
  if (camera->moving) {
    float s = close > open ? (*time - open) / (close - open) : 0.0f;
    origin = sb_mix(origin, load3g(camera->origin_end), s);
    float3 look = sb_mix(load3g(camera->look_at), load3g(camera->look_at_end), s);
    forward = sb_normalize(look - origin);
    float3 r = sb_normalize(sb_cross(forward, load3g(camera->world_up)));
    float tan_half = camera->world_up[3];
    right = r * (tan_half * (float)camera->width / (float)camera->height);
    up = sb_cross(r, forward) * tan_half;
  }
  float x = 2.0f * fx / (float)camera->width - 1.0f;
  float y = 1.0f - 2.0f * fy / (float)camera->height;
  float3 dir = sb_normalize(forward + x * right + y * up);
  if (camera->lens_radius > 0.0f) {
    /* Every ray through the lens from this film point meets the pinhole ray on
     * the plane in focus, focus_distance along the view direction. */
    float3 focus = origin + dir * (camera->focus_distance / sb_dot(dir, forward));
    float2 l = concentric_disk(u_lens) * camera->lens_radius;
    origin = origin + l.x * sb_normalize(right) + l.y * sb_normalize(up);
    dir = sb_normalize(focus - origin);
  }
  *o = origin;
  *d = dir;
}

#endif
