/* Lights as shading sees them: each can sample a point on itself as seen from a
 * shading point, and an area light can be hit by a ray (camera and reflected
 * rays see its radiance). Area lights emit uniform radiance L from both faces
 * (quad, disk) or outward (sphere); a shadow feeler to a sampled point y brings
 * L * G / pi times the local model's n.l-weighted term, with G the solid angle
 * the sample stands for (A cos_y / r^2 for area sampling, the cone's solid angle
 * for a sphere), so a white diffuse surface facing a light that fills its
 * hemisphere has the light's radiance. A point light brings its intensity. */
#ifndef PRISM_SHADING_LIGHT_H
#define PRISM_SHADING_LIGHT_H

#include "common/math.h"
#include "sampling/warp.h"
#include "shading/frame.h"
#include "shared/light_gpu.h"

/* The point on the light that a shadow feeler from p goes to, for sample u in
 * [0, 1)^2: unit direction *dir, distance *dist, and *scale, the factor of the
 * local model's term (rgb). Returns false when the sample brings nothing. */
inline bool light_sample(__global const LightGpu* light, float3 p, float2 u, float3* dir, float* dist,
                         float3* scale) {
  float3 color = load3g(light->color);
  if (light->type == LIGHT_POINT) {
    float3 to_light = load3g(light->position) - p;
    *dist = sb_length(to_light);
    *dir = to_light / *dist;
    *scale = color;
    return true;
  }
#ifndef PRISM_AREA_LIGHTS /* built for scenes with area lights (host: kernelFeatures) */
  return false;
#else
  float3 c = load3g(light->position);
  if (light->type == LIGHT_SPHERE) {
    /* Uniform in the cone of directions the sphere fills (its visible cap). */
    float r = light->position[3];
    float3 to_c = c - p;
    float dc = sb_length(to_c);
    float3 w = to_c / dc;
    float3 t, b;
    orthonormal_basis(w, &t, &b);
    float phi = 2.0f * PRISM_PI * u.y;
    float solid_angle;
    float cos_t, sin_t;
    if (dc > r) {
      float sin2_max = (r * r) / (dc * dc);
      float cos_max = sqrt(fmax(0.0f, 1.0f - sin2_max));
      cos_t = 1.0f - u.x * (1.0f - cos_max);
      solid_angle = 2.0f * PRISM_PI * (1.0f - cos_max);
    } else { /* inside: every direction meets the sphere */
      cos_t = 1.0f - 2.0f * u.x;
      solid_angle = 4.0f * PRISM_PI;
    }
    sin_t = sqrt(fmax(0.0f, 1.0f - cos_t * cos_t));
    float3 d = sb_normalize(sin_t * sb_cos(phi) * t + sin_t * sb_sin(phi) * b + cos_t * w);
    /* First crossing of the sphere along d (the exit one from inside). */
    float proj = sb_dot(to_c, d);
    float disc = fmax(0.0f, r * r - (dc * dc - proj * proj));
    float root = sqrt(disc);
    float hit = dc > r ? proj - root : proj + root;
    if (!(hit > 0.0f)) return false;
    *dir = d;
    *dist = hit;
    *scale = color * (solid_angle / PRISM_PI);
    return true;
  }
  float3 e1 = load3g(light->edge1), e2 = load3g(light->edge2);
  float3 y;
  if (light->type == LIGHT_QUAD) {
    y = c + u.x * e1 + u.y * e2;
  } else { /* disk: e1 and e2 are its orthogonal radii */
    float2 d = concentric_disk(u);
    y = c + d.x * e1 + d.y * e2;
  }
  float3 to_y = y - p;
  float r2 = sb_dot(to_y, to_y);
  if (!(r2 > 0.0f)) return false;
  float r = sqrt(r2);
  *dir = to_y / r;
  float cos_y = fabs(sb_dot(load3g(light->normal), *dir));
  *dist = r;
  *scale = color * (light->color[3] * cos_y / (r2 * PRISM_PI));
  return cos_y > 0.0f;
#endif
}

/* The nearest t in (0, tmax) where ray (o, d) meets area light `light`, or
 * tmax when it misses (point lights are never hit). */
inline float light_hit(__global const LightGpu* light, float3 o, float3 d, float tmax) {
  if (light->type == LIGHT_POINT) return tmax;
  float3 c = load3g(light->position);
  if (light->type == LIGHT_SPHERE) {
    float r = light->position[3];
    float3 oc = o - c;
    float a = sb_dot(d, d), b = sb_dot(oc, d), q = sb_dot(oc, oc) - r * r;
    float disc = b * b - a * q;
    if (disc < 0.0f) return tmax;
    float root = sqrt(disc);
    float t = (-b - root) / a;
    if (!(t > 0.0f)) t = (-b + root) / a;
    return t > 0.0f && t < tmax ? t : tmax;
  }
  float3 n = load3g(light->normal);
  float dn = sb_dot(d, n);
  if (dn == 0.0f) return tmax;
  float t = sb_dot(c - o, n) / dn;
  if (!(t > 0.0f && t < tmax)) return tmax;
  float3 q = o + t * d - c;
  float3 e1 = load3g(light->edge1), e2 = load3g(light->edge2);
  float a = sb_dot(q, e1) / sb_dot(e1, e1), b = sb_dot(q, e2) / sb_dot(e2, e2);
  if (light->type == LIGHT_QUAD) return a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f ? t : tmax;
  return a * a + b * b <= 1.0f ? t : tmax; /* disk: edges are orthogonal radii */
}

#endif
