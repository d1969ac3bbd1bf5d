/* count_rays: the first pass of stable queue compaction. Work-item b counts,
 * from the slot tags (shared/ray_gpu.h), the live rays of each kind in slots
 * [b*block, (b+1)*block); scan_blocks turns the counts into output offsets (an
 * exclusive scan), then scatter_rays moves them. The last column counts the
 * shadow feelers shade traced itself (tagged on live and empty slots alike):
 * they are no part of the queue. */
#include "shared/ray_gpu.h"

__kernel void count_rays(__global const int* tags, int count, int block, __global int* counts) {
  int b = get_global_id(0);
  int begin = b * block;
  if (begin >= count) return;
  int end = min(count, begin + block);
  int c[RAY_COUNT_COLUMNS] = {0, 0, 0, 0, 0};
  for (int i = begin; i < end; ++i) {
    int tag = tags[i];
    int kind = SLOT_KIND(tag);
    if (kind >= 0) c[kind] += 1;
    c[RAY_COUNT_FEELERS] += SLOT_FEELERS(tag);
  }
  for (int j = 0; j < RAY_COUNT_COLUMNS; ++j) counts[b * RAY_COUNT_COLUMNS + j] = c[j];
}
