/* scan: an exclusive prefix sum of n non-negative ints on the device, in three
 * launches (host/render/device_scan.cpp): scan_block_sums adds up each block of
 * `block` entries, scan_block_offsets (one work-item) turns the block sums into
 * block offsets, scan_apply writes every entry's offset and, from the last
 * block, the total at out[n]. Sums are taken in 64 bits and stored saturated at
 * INT_MAX, so a total that does not fit an int reads INT_MAX, never wraps.
 * Sequential within a block: the order of the additions, so the result, is
 * fixed (integer sums are exact anyway). */

inline int scan_saturate(long s) { return s > INT_MAX ? INT_MAX : (int)s; }

__kernel void scan_block_sums(__global const int* in, int n, int block, __global int* sums) {
  int b = get_global_id(0);
  int begin = b * block;
  if (begin >= n) return;
  int end = min(n, begin + block);
  long s = 0;
  for (int i = begin; i < end; ++i) s += in[i];
  sums[b] = scan_saturate(s);
}

__kernel void scan_block_offsets(__global int* sums, int blocks) {
  if (get_global_id(0) != 0) return;
  long total = 0;
  for (int b = 0; b < blocks; ++b) {
    int s = sums[b];
    sums[b] = scan_saturate(total);
    total += s;
  }
  sums[blocks] = scan_saturate(total);
}

__kernel void scan_apply(__global const int* in, int n, int block, __global const int* offsets, int blocks,
                         __global int* out) {
  int b = get_global_id(0);
  int begin = b * block;
  if (begin >= n) return;
  int end = min(n, begin + block);
  long s = offsets[b];
  for (int i = begin; i < end; ++i) {
    out[i] = scan_saturate(s);
    s += in[i];
  }
  if (b == blocks - 1) out[n] = scan_saturate(s);
}
