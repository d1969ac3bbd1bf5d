/* scatter_rays: the second pass of stable queue compaction (see count_rays).
 * Order is kept, so a queue sorted by pixel stays sorted. */
#include "shared/ray_gpu.h"

__kernel void scatter_rays(__global const RayGpu* in, __global const int* tags, int count, int block,
                           __global const int* offsets, __global RayGpu* out) {
  int b = get_global_id(0);
  int begin = b * block;
  if (begin >= count) return;
  int end = min(count, begin + block);
  int o = offsets[b];
  for (int i = begin; i < end; ++i)
    if (SLOT_KIND(tags[i]) >= 0) out[o++] = in[i];
}
