/* Textures on the diffuse colour: a procedural checker, or an image sampled
 * bilinearly with a wrap mode (its texels already in linear light: the host
 * decoded sRGB, host/scene/image_texture.h). */
#ifndef PRISM_SHADING_TEXTURE_H
#define PRISM_SHADING_TEXTURE_H

#include "common/math.h"
#include "shared/material_gpu.h"

/* Texel column or row i of n under a wrap mode. */
inline int texture_wrap(int i, int n, int mode) {
  if (mode == TEXTURE_WRAP_CLAMP) return clamp(i, 0, n - 1);
  if (mode == TEXTURE_WRAP_MIRROR) {
    int k = i % (2 * n);
    if (k < 0) k += 2 * n;
    return k < n ? k : 2 * n - 1 - k;
  }
  int k = i % n;
  return k < 0 ? k + n : k;
}

/* Bilinear filtering at texture coordinates st (0..1 across the image, v up,
 * so t = 0 is the bottom row): texel centres at (i + 0.5) / width. */
inline float3 texture_image(__global const MaterialGpu* m, __global const float4* texels, float2 st) {
  int w = m->image_width, h = m->image_height;
  /* Far outside [0, 1] the wrapped position is what matters: keep the int
   * conversion in range (a repeat or mirror period is a whole number of texels). */
  float x = clamp(st.x * w - 0.5f, -1e9f, 1e9f), y = clamp((1.0f - st.y) * h - 0.5f, -1e9f, 1e9f);
  float x0 = floor(x), y0 = floor(y);
  float fx = x - x0, fy = y - y0;
  int i0 = (int)x0, j0 = (int)y0;
  int ia = texture_wrap(i0, w, m->wrap), ib = texture_wrap(i0 + 1, w, m->wrap);
  int ja = texture_wrap(j0, h, m->wrap), jb = texture_wrap(j0 + 1, h, m->wrap);
  __global const float4* img = texels + m->image_offset;
  float3 top = sb_mix(img[ja * w + ia].xyz, img[ja * w + ib].xyz, fx);
  float3 bottom = sb_mix(img[jb * w + ia].xyz, img[jb * w + ib].xyz, fx);
  return sb_mix(top, bottom, fy);
}

/* Colour that multiplies ambient and diffuse at surface coordinates uv. */
inline float3 texture_color(__global const MaterialGpu* m, __global const float4* texels, float2 uv) {
  if (m->texture == TEXTURE_IMAGE) return texture_image(m, texels, uv / m->texture_scale);
  if (m->texture != TEXTURE_CHECKER) return (float3)(1.0f, 1.0f, 1.0f);
  /* The parity in float: a cell number beyond the int range (uv near a
   * plane's horizon) would make the conversion undefined. */
  float2 cell = floor(uv / m->texture_scale);
  float sum = cell.x + cell.y;
  bool odd = sum - 2.0f * floor(0.5f * sum) != 0.0f;
  return odd ? load3g(m->checker2) : load3g(m->checker1);
}

#endif
