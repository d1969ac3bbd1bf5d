/* scan_blocks: the middle pass of stable queue compaction, on the device so the
 * host only reads back the totals. One work-item turns the per-block counts of
 * count_rays (RAY_COUNT_COLUMNS per block) into each block's output offset (an
 * exclusive scan of the block's live rays) and writes, into totals, the live
 * rays of each kind, their sum, then the feelers shade traced. The blocks are few (a queue of 2^17 slots has
 * 512), so a sequential scan costs less than another launch would. */
#include "shared/ray_gpu.h"

__kernel void scan_blocks(__global const int* counts, int blocks, __global int* offsets, __global int* totals) {
  if (get_global_id(0) != 0) return;
  int kinds[RAY_KIND_COUNT] = {0, 0, 0, 0};
  int total = 0, feelers = 0;
  for (int b = 0; b < blocks; ++b) {
    offsets[b] = total;
    for (int kind = 0; kind < RAY_KIND_COUNT; ++kind) {
      int c = counts[b * RAY_COUNT_COLUMNS + kind];
      kinds[kind] += c;
      total += c;
    }
    feelers += counts[b * RAY_COUNT_COLUMNS + RAY_COUNT_FEELERS];
  }
  for (int kind = 0; kind < RAY_KIND_COUNT; ++kind) totals[kind] = kinds[kind];
  totals[RAY_TOTAL_LIVE] = total;
  totals[RAY_TOTAL_FEELERS] = feelers;
}
