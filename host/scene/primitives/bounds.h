// Float boxes and the cells of spatial subdivisions, as the primitive kinds
// and the acceleration builders share them.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

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

// std::nextafter(f, +inf) and (f, -inf), inline and without branches: the
// builders bound every primitive with six of them, and the library call was a
// tenth of a 1M-triangle BVH's set-up; then the branches on the value's sign
// and on which way a double rounds, which a mesh around the origin takes either
// way at random, were most of the bounding's time (about 190 cycles a triangle
// on the 69k bunny). A float's neighbour is the next integer of the same sign
// in its bits, except at zero and the infinities; the selects below compile to
// conditional moves.
inline float nextFloatUp(float f) {
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  const std::uint32_t stepped = (bits >> 31) != 0 ? bits - 1 : bits + 1;  // negative: towards zero
  const bool stays = !(f < std::numeric_limits<float>::infinity());       // +inf and NaN
  std::uint32_t out = stays ? bits : stepped;
  out = f == 0 ? 1u : out;  // either zero: the least positive denormal
  std::memcpy(&f, &out, sizeof f);
  return f;
}
inline float nextFloatDown(float f) { return -nextFloatUp(-f); }

// The nearest float <= x and >= x: outward rounding keeps boxes conservative.
inline float roundDown(double x) {
  const float f = static_cast<float>(x);
  const float below = nextFloatDown(f);
  return double(f) > x ? below : f;
}
inline float roundUp(double x) {
  const float f = static_cast<float>(x);
  const float above = nextFloatUp(f);
  return double(f) < x ? above : f;
}

}  // namespace prism
