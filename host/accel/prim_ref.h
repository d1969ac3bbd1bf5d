// Boxes and the primitives a builder works on: the world box of every object
// (exact float bounds for triangles, untransformed spheres and boxes; a
// conservatively padded box for transformed ones) and the split of the scene
// into bounded primitives (go into the tree) and unbounded ones (planes, and
// anything whose bounds are not finite: tested by every ray).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "kernels/shared/object_gpu.h"

namespace prism {

struct Aabb {
  float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                 std::numeric_limits<float>::infinity()};
  float hi[3] = {-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                 -std::numeric_limits<float>::infinity()};

  bool empty() const { return !(lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2]); }
  void extend(const Aabb& b) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = b.lo[a] < lo[a] ? b.lo[a] : lo[a];
      hi[a] = b.hi[a] > hi[a] ? b.hi[a] : hi[a];
    }
  }
  void extend(const float p[3]) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = p[a] < lo[a] ? p[a] : lo[a];
      hi[a] = p[a] > hi[a] ? p[a] : hi[a];
    }
  }
  // Surface area (0 for an empty box), in double so huge scenes do not overflow.
  double area() const {
    if (empty()) return 0;
    double dx = double(hi[0]) - lo[0], dy = double(hi[1]) - lo[1], dz = double(hi[2]) - lo[2];
    return 2 * (dx * dy + dy * dz + dz * dx);
  }
};

// Cell boxes during subdivision: double, but every coordinate is a float value
// the device also uses (the root box and split planes are floats).
struct CellBox {
  double lo[3], hi[3];
  double area() const {
    double dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
    return 2 * (dx * dy + dy * dz + dz * dx);
  }
};

inline CellBox toCell(const Aabb& b) { return {{b.lo[0], b.lo[1], b.lo[2]}, {b.hi[0], b.hi[1], b.hi[2]}}; }

// World bounds of an object; false when it has none (a plane, or non-finite data).
// A moving object (has_transform == OBJECT_MOVING) must sit in its scene's object
// array, its motion record further on in it: its box covers its whole motion.
bool objectBounds(const ObjectGpu& object, Aabb* bounds);

// Linear bounds (Embree's linear motion blur): boxes at shutter open and close
// such that lerp(open, close, s) holds the object at every s in [0, 1] of its
// motion. A static object's two boxes are its objectBounds.
bool objectLinearBounds(const ObjectGpu& object, Aabb* open, Aabb* close);

struct PrimitiveSet {
  std::vector<std::int32_t> bounded;  // object indices, in object order
  std::vector<Aabb> bounds;           // bounds[i] is the box of object bounded[i] (over its whole motion)
  std::vector<std::int32_t> unbounded;
  Aabb scene;  // union of `bounds`
  // Whether some bounded primitive moves, the shutter its motion spans, and
  // then the linear bounds of every bounded primitive (objectLinearBounds).
  bool moving = false;
  float shutter_open = 0, shutter_close = 0;
  std::vector<Aabb> bounds_open, bounds_close;
};

PrimitiveSet gatherPrimitives(const std::vector<ObjectGpu>& objects);

// The primitives of an object array: the entries before the motion records
// that close it (kernels/shared/motion_gpu.h), if any.
std::size_t primitiveCount(const std::vector<ObjectGpu>& objects);

// The nearest float <= x and >= x: outward rounding keeps boxes conservative.
float roundDown(double x);
float roundUp(double x);

}  // namespace prism
