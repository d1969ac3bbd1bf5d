/* accumulate: adds a queue of contributions, sorted by film key, into the film
 * (4 floats per key: in a render, one entry per primary sample). The first
 * work-item of each run of equal keys sums the run in queue order, so each entry
 * has one writer per launch and the sum is the same on every run (float atomics
 * would make the order, and so the image, vary).
 *
 * first_bad: the lowest queue index whose contribution is not finite (NaN or
 * inf) is kept there by an atomic minimum; the host reads it back only for a
 * render with check_nan, and then reads that contribution's ray (the queue is
 * sorted by key, so the lowest index is the lowest sample key).
 *
 * film_first: the key of the film's first entry (a device that holds a window
 * of the frame's film, one unit of it, rather than the whole). */
#include "shared/contribution_gpu.h"

__kernel void accumulate(__global const ContributionGpu* c, int count, __global float* film, int film_first,
                         __global int* first_bad) {
  int k = get_global_id(0);
  if (k >= count) return;
  if (!(isfinite(c[k].r) && isfinite(c[k].g) && isfinite(c[k].b) && isfinite(c[k].a))) atomic_min(first_bad, k);
  int key = c[k].pixel;
  if (k > 0 && c[k - 1].pixel == key) return;
  float4 sum = (float4)(0.0f);
  for (int j = k; j < count && c[j].pixel == key; ++j) sum += (float4)(c[j].r, c[j].g, c[j].b, c[j].a);
  __global float* f = film + 4 * (size_t)(key - film_first);
  f[0] += sum.x;
  f[1] += sum.y;
  f[2] += sum.z;
  f[3] += sum.w;
}
