/* Procedural textures on the diffuse colour. */
#ifndef PRISM_SHADING_TEXTURE_H
#define PRISM_SHADING_TEXTURE_H

#include "common/math.h"
#include "shared/material_gpu.h"

/* Colour that multiplies ambient and diffuse at surface coordinates uv. */
inline float3 texture_color(__global const MaterialGpu* m, float2 uv) {
  if (m->texture != TEXTURE_CHECKER) return (float3)(1.0f, 1.0f, 1.0f);
  float2 cell = floor(uv / m->texture_scale);
  int parity = ((int)cell.x + (int)cell.y) & 1;
  return parity ? load3g(m->checker2) : load3g(m->checker1);
}

#endif
