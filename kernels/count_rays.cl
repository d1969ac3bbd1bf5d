/* count_rays: the first pass of stable queue compaction. Work-item b counts the
 * live rays of each kind in slots [b*block, (b+1)*block); scan_blocks turns the
 * counts into output offsets (an exclusive scan), then scatter_rays moves them.
 * The last column counts the shadow feelers shade traced itself (RayGpu.feelers,
 * in live and empty slots alike): they are no part of the queue. */
#include "shared/ray_gpu.h"

__kernel void count_rays(__global const RayGpu* rays, int count, int block, __global int* counts) {
  int b = get_global_id(0);
  int begin = b * block;
  if (begin >= count) return;
  int end = min(count, begin + block);
  int c[RAY_COUNT_COLUMNS] = {0, 0, 0, 0, 0};
  for (int i = begin; i < end; ++i) {
    int kind = rays[i].kind;
    if (kind >= 0) c[kind] += 1;
    c[RAY_COUNT_FEELERS] += rays[i].feelers;
  }
  for (int j = 0; j < RAY_COUNT_COLUMNS; ++j) counts[b * RAY_COUNT_COLUMNS + j] = c[j];
}
