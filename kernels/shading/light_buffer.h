/* Shadow feelers to point lights: through the light buffer when the program
 * is built with PRISM_LIGHT_BUFFER (host/render/light_buffer.h), else through
 * the acceleration structure. The light buffer: the feeler from p towards
 * light l lies along the direction p - L from the light; that direction picks
 * a face of the light's cube (its largest component) and a cell on it, whose
 * list holds every bounded primitive the feeler could meet; planes are tested
 * by every feeler. The same transmittance as the structure's: each primitive
 * met multiplies the light by its k_trans once. */
#ifndef PRISM_SHADING_LIGHT_BUFFER_H
#define PRISM_SHADING_LIGHT_BUFFER_H

#include "accel/accel.h"

#define LIGHT_BUFFER_PARAMS                                                                                   \
  __global const int *light_buffer_cells, __global const int *light_buffer_ids,                              \
      __global const float4 *light_buffer_windows, int light_buffer_resolution
#define LIGHT_BUFFER_ARGS light_buffer_cells, light_buffer_ids, light_buffer_windows, light_buffer_resolution

/* The index of the cell direction w (from the light) falls in, on a cube of
 * res x res cells a face: faces +x, -x, +y, -y, +z, -z, rows j, columns i,
 * each face's cells over its window (u0, cells per unit u, v0, cells per unit
 * v) of (u, v) = (w_b, w_c) / |w_a|. */
inline int light_buffer_cell(float3 w, int res, __global const float4* windows) {
  float3 a = fabs(w);
  int face;
  float m, s, t;
  if (a.x >= a.y && a.x >= a.z) {
    face = w.x > 0.0f ? 0 : 1, m = a.x, s = w.y, t = w.z;
  } else if (a.y >= a.z) {
    face = w.y > 0.0f ? 2 : 3, m = a.y, s = w.x, t = w.z;
  } else {
    face = w.z > 0.0f ? 4 : 5, m = a.z, s = w.x, t = w.y;
  }
  float4 win = windows[face];
  /* Clamped in float before the conversion, which is defined only for values
   * that fit an int (and NaN, where m is 0, goes to 0). */
  float top = (float)(res - 1);
  int i = (int)fmin(fmax(floor((s / m - win.x) * win.y), 0.0f), top);
  int j = (int)fmin(fmax(floor((t / m - win.z) * win.w), 0.0f), top);
  return (face * res + j) * res + i;
}

/* The light a feeler from o along d (unit, towards point light `l` at
 * `light_pos`, `dist` away) carries. */
PRISM_HOT float point_light_transmittance(ACCEL_PARAMS, LIGHT_BUFFER_PARAMS, __global const MaterialGpu* materials,
                                          int l, float3 light_pos, float3 o, float3 d, float time, float dist) {
#ifdef PRISM_LIGHT_BUFFER
  if (!accel_ray_walkable(o, d, 0.0f, dist)) return 1.0f;
  int res = light_buffer_resolution;
  int cell = 1 + l * 6 * res * res + light_buffer_cell(o - light_pos, res, light_buffer_windows + 6 * l); /* entry 0: the unbounded */
  int first = light_buffer_cells[2 * cell], count = light_buffer_cells[2 * cell + 1];
  float carried = 1.0f;
  for (int k = 0; k < count && carried > 0.0f; ++k) {
    int prim = light_buffer_ids[first + k];
    float t, u, v;
    if (prim_intersect(geom, prim, o, d, time, 0.0f, dist, &t, &u, &v))
      carried *= accel_transmit(materials, geom, prim);
  }
  for (int k = 0; k < light_buffer_cells[1] && carried > 0.0f; ++k) {
    int prim = light_buffer_ids[light_buffer_cells[0] + k];
    float t, u, v;
    if (prim_intersect(geom, prim, o, d, time, 0.0f, dist, &t, &u, &v))
      carried *= accel_transmit(materials, geom, prim);
  }
  return carried;
#else
  return accel_transmittance(ACCEL_ARGS, materials, o, d, time, 0.0f, dist);
#endif
}

#endif
