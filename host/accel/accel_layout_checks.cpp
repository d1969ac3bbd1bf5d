// Compile-time checks that the host lays out the acceleration structures'
// shared structs as OpenCL C does (plain 4-byte fields, no padding; sizes in
// multiples the kernels rely on when they read nodes as float4 / float8).
#include <cstddef>

#include "accel/accel_structure.h"
#include "kernels/shared/bsp_node_gpu.h"
#include "kernels/shared/bvh_node_gpu.h"
#include "kernels/shared/octree_node_gpu.h"
#include "kernels/shared/tri_packet_gpu.h"

static_assert(sizeof(TriPacketGpu) == 160 && offsetof(TriPacketGpu, e1x) == 48 && offsetof(TriPacketGpu, e2x) == 96 &&
                  offsetof(TriPacketGpu, prim) == 144,
              "TriPacketGpu: ten float4, prim ids last");
static_assert(sizeof(BvhNodeGpu) == 224 && offsetof(BvhNodeGpu, hi_x) == 32 && offsetof(BvhNodeGpu, lo_y) == 64 &&
                  offsetof(BvhNodeGpu, lo_z) == 128 && offsetof(BvhNodeGpu, child) == 192,
              "BvhNodeGpu: seven float8");
static_assert(sizeof(BvhMotionBoundsGpu) == 192, "BvhMotionBoundsGpu: six float8");
static_assert(sizeof(OctreeNodeGpu) == 48 && offsetof(OctreeNodeGpu, first) == 12 &&
                  offsetof(OctreeNodeGpu, child_mask) == 28 && offsetof(OctreeNodeGpu, cx) == 32 &&
                  offsetof(OctreeNodeGpu, packet_count) == 44,
              "OctreeNodeGpu layout: three float4");
static_assert(sizeof(BspNodeGpu) == 8 && offsetof(BspNodeGpu, payload) == 4, "BspNodeGpu layout");
static_assert(sizeof(prism::AccelWord) == 16 && alignof(prism::AccelWord) == 16, "AccelWord is one float4");
static_assert(sizeof(BvhNodeGpu) % sizeof(prism::AccelWord) == 0 && sizeof(OctreeNodeGpu) % sizeof(prism::AccelWord) == 0,
              "nodes fill whole words");
