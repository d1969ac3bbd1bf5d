/* resolve: reconstructs pixels [first_pixel, first_pixel + count) from per-sample
 * radiance (rgba, 4 floats a sample, numbered as kernels/supersample.cl numbers
 * them): pixel = sum(w * L) / sum(w) over the samples within the filter's radius of
 * the pixel centre. Each work-item gathers one pixel in a fixed order, so there are
 * no atomics and the result is the same on every run. Per-pixel modes look only at
 * the pixels a sample of which can fall within the radius; quincunx is by
 * definition the tent of radius 1 on its five points: centre 1/2, corners 1/8.
 * sample_first: the number of the first sample xy and radiance hold (a window
 * of the frame's samples that covers every sample the pixels reach; the host
 * checks it). */
#include "sampling/filters.h"
#include "sampling/sample_modes.h"

__kernel void resolve(int mode, int filter, int width, int height, int spp, __global const float* xy,
                      __global const float* radiance, int sample_first, int first_pixel, int count,
                      __global float* film) {
  int k = get_global_id(0);
  if (k >= count) return;
  int pixel = first_pixel + k;
  int i = pixel % width, j = pixel / width;
  float4 out;

  if (mode == AA_MODE_QUINCUNX) {
    int c00 = j * (width + 1) + i - sample_first, c01 = (j + 1) * (width + 1) + i - sample_first;
    float4 centre = vload4((width + 1) * (height + 1) + pixel - sample_first, radiance);
    float4 sum = (vload4(c00, radiance) + vload4(c00 + 1, radiance)) + (vload4(c01, radiance) + vload4(c01 + 1, radiance));
    out = 0.5f * centre + 0.125f * sum;
    vstore4(out, pixel, film);
    return;
  }

  /* Samples lie inside their own pixel, so only pixels within ceil(r - 1/2) rows
   * and columns can hold samples within the radius r. */
  float radius = filter_radius(filter);
  int reach = (int)ceil(radius - 0.5f);
  float cx = (float)i + 0.5f, cy = (float)j + 0.5f;
  float4 sum = (float4)(0.0f);
  float wsum = 0.0f;
  for (int pj = max(0, j - reach); pj <= min(height - 1, j + reach); ++pj)
    for (int pi = max(0, i - reach); pi <= min(width - 1, i + reach); ++pi) {
      int base = (pj * width + pi) * spp - sample_first; /* the host keeps the sample count under 2^31 */
      for (int s = 0; s < spp; ++s) {
        size_t at = 2 * (size_t)(base + s);
        float w = filter_weight(filter, xy[at] - cx, xy[at + 1] - cy);
        if (w != 0.0f) {
          sum += w * vload4(base + s, radiance);
          wsum += w;
        }
      }
    }
  if (wsum > 0.0f) {
    out = sum / wsum;
  } else {
    /* Only a negative-lobed filter (Mitchell) with very few samples gets here: fall
     * back to the plain mean of the pixel's own samples. */
    out = (float4)(0.0f);
    for (int s = 0; s < spp; ++s) out += vload4(pixel * spp + s - sample_first, radiance);
    out /= (float)spp;
  }
  vstore4(out, pixel, film);
}
