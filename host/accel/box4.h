// Four-lane boxes for the builders' hot loops: x, y and z in lanes 0-2 of a
// GCC/Clang vector (SSE on x86, NEON on ARM), lane 3 carried along and never
// read. One min and one max extend a box by another, where Aabb takes six
// scalar comparisons.
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>

#include "scene/primitives/bounds.h"

namespace prism {

using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));

// 16 bytes from p, which need not be aligned.
inline Float4 loadFloat4(const void* p) {
  Float4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Lanes 0-2 of v with lane 3 cleared, so that whatever it held (an id's bits)
// cannot turn into a NaN or an infinity in arithmetic.
inline Float4 xyzOnly(Float4 v) { return reinterpret_cast<Float4>(reinterpret_cast<Int4>(v) & Int4{-1, -1, -1, 0}); }

// The same choice as Aabb::extend: the new value where it is strictly beyond.
inline Float4 lowerOf(Float4 candidate, Float4 current) { return candidate < current ? candidate : current; }
inline Float4 upperOf(Float4 candidate, Float4 current) { return candidate > current ? candidate : current; }

struct Box4 {
  static constexpr float kInf = std::numeric_limits<float>::infinity();
  Float4 lo = {kInf, kInf, kInf, kInf};
  Float4 hi = {-kInf, -kInf, -kInf, -kInf};

  void extend(Float4 l, Float4 h) {
    lo = lowerOf(l, lo);
    hi = upperOf(h, hi);
  }
  void extend(const Box4& b) { extend(b.lo, b.hi); }
  // A point: both ends.
  void extend(Float4 p) { extend(p, p); }

  Aabb aabb() const {
    Aabb b;
    for (int a = 0; a < 3; ++a) {
      b.lo[a] = lo[a];
      b.hi[a] = hi[a];
    }
    return b;
  }
  // Surface area, 0 for an empty box; in double, as Aabb::area, so that huge
  // scenes do not overflow.
  double area() const {
    const double x = double(hi[0]) - lo[0], y = double(hi[1]) - lo[1], z = double(hi[2]) - lo[2];
    if (!(x >= 0 && y >= 0 && z >= 0)) return 0;
    return 2 * (x * y + y * z + z * x);
  }
};

}  // namespace prism
