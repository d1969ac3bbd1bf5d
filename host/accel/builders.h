// The three builders behind buildAccel (accel_structure.cpp). Each fills the
// node buffer, the leaf packets and the statistics of `out`; the caller has
// already put the unbounded primitives aside and will time the build.
#pragma once

#include <cstring>
#include <string>
#include <vector>

#include "accel/accel_structure.h"
#include "accel/prim_ref.h"

namespace prism {

// Binned SAH BVH (Wald 2007) built as a binary tree on all cores, then
// collapsed into 8-wide nodes (bvh_builder.cpp).
void buildBvh(const std::vector<ObjectGpu>& objects, const PrimitiveSet& prims, const AccelBuildOptions& options,
              DeviceAccel& out);

// Adaptive octree over a cube around the scene (octree_builder.cpp).
void buildOctree(const std::vector<ObjectGpu>& objects, const PrimitiveSet& prims, const AccelBuildOptions& options,
                 DeviceAccel& out);

// SAH kd-tree with axis-aligned planes (bsp_builder.cpp).
void buildBsp(const std::vector<ObjectGpu>& objects, const PrimitiveSet& prims, const AccelBuildOptions& options,
              DeviceAccel& out);

// Shared by the builders: the scene box header of the node buffer, the stack
// depth option, and duplication statistics from per-primitive reference counts.
void writeSceneHeader(const Aabb& scene, DeviceAccel& out);
std::string stackOption(int entries);
void finishReferenceStats(const std::vector<int>& refs_per_prim, AccelStats& stats);

// Appends plain structs to the node buffer as 16-byte words (the last word is
// zero-padded); returns the first word's index.
template <typename T>
std::size_t appendNodeWords(std::vector<AccelWord>& words, const T* nodes, std::size_t count) {
  std::size_t first = words.size();
  std::size_t bytes = sizeof(T) * count;
  words.resize(first + (bytes + sizeof(AccelWord) - 1) / sizeof(AccelWord), AccelWord{});
  if (bytes) std::memcpy(static_cast<void*>(words.data() + first), nodes, bytes);
  return first;
}

}  // namespace prism
