// Boxes and the primitives a builder works on: the world box of every object
// (exact float bounds for triangles, untransformed spheres and boxes; a
// conservatively padded box for transformed ones) and the split of the scene
// into bounded primitives (go into the tree) and unbounded ones (planes, and
// anything whose bounds are not finite: tested by every ray).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "accel/uninitialised_vector.h"
#include "kernels/shared/object_gpu.h"
#include "scene/primitives/bounds.h"

namespace prism {

// World bounds of an object; false when it has none (a plane, or non-finite data).
// A moving object (has_transform == OBJECT_MOVING) must sit in its scene's object
// array, its motion record further on in it: its box covers its whole motion.
bool objectBounds(const ObjectGpu& object, Aabb* bounds);

// Linear bounds (Embree's linear motion blur): boxes at shutter open and close
// such that lerp(open, close, s) holds the object at every s in [0, 1] of its
// motion. A static object's two boxes are its objectBounds.
bool objectLinearBounds(const ObjectGpu& object, Aabb* open, Aabb* close);

struct PrimitiveSet {
  // Written in place by gatherPrimitives' threads (uninitialised_vector.h).
  UninitialisedVector<std::int32_t> bounded;  // object indices, in object order
  UninitialisedVector<Aabb> bounds;           // bounds[i] is the box of object bounded[i] (over its whole motion)
  std::vector<std::int32_t> unbounded;
  Aabb scene;  // union of `bounds`
  // Whether some bounded primitive moves, the shutter its motion spans, and
  // then the linear bounds of every bounded primitive (objectLinearBounds).
  bool moving = false;
  float shutter_open = 0, shutter_close = 0;
  // Over every primitive, bounded or not: bit k set where some has type k
  // (OBJECT_*), and whether some moves (primitiveKernelOptions).
  unsigned kinds = 0;
  bool any_moving = false;
  // Every primitive a static world-space triangle (leaf_packets.h,
  // isPacketTriangle), none unbounded: a mesh scene.
  bool triangles_only = false;
  std::vector<Aabb> bounds_open, bounds_close;
};

// The primitives' boxes, computed on `threads` threads (0: every core) for
// scenes of at least kParallelBoundsPrims; the result does not depend on it.
constexpr std::size_t kParallelBoundsPrims = 16384;
PrimitiveSet gatherPrimitives(const std::vector<ObjectGpu>& objects, int threads = 0);

// The primitives of an object array: the entries before the mesh headers,
// motion and data records that close it (kernels/shared/motion_gpu.h, object_gpu.h), if any.
std::size_t primitiveCount(const std::vector<ObjectGpu>& objects);
// The kernel build option that compiles moving objects' intersection
// (kernels/geometry/motion.h); programs without it never see a moving object.
constexpr const char* kMotionKernelOption = "-DPRISM_MOTION";

// The build options the primitives ask of the kernels, from one pass over
// them: kMotionKernelOption where some primitive moves, and -DPRISM_KINDS
// (kernels/geometry/object.h) naming the kinds to intersect: spheres, boxes,
// planes and triangles always, the larger kinds only where the scene has some.
std::string primitiveKernelOptions(const std::vector<ObjectGpu>& objects);
// The same from what gatherPrimitives found (PrimitiveSet::kinds and moving).
std::string primitiveKernelOptions(unsigned kinds, bool moving);

}  // namespace prism
