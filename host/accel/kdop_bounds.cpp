#include "accel/kdop_bounds.h"

#include <cmath>
#include <limits>

#include "accel/leaf_packets.h"

namespace prism {
namespace {

// The float at or below x, and at or above it.
float floatDown(double x) {
  float f = static_cast<float>(x);
  return f > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float floatUp(double x) {
  float f = static_cast<float>(x);
  return f < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace

DiagonalSlabs DiagonalSlabs::empty() {
  DiagonalSlabs s;
  for (int j = 0; j < BVH_KDOP_DIAGONALS; ++j) {
    s.lo[j] = std::numeric_limits<float>::infinity();
    s.hi[j] = -std::numeric_limits<float>::infinity();
  }
  return s;
}

void DiagonalSlabs::extend(const DiagonalSlabs& other) {
  for (int j = 0; j < BVH_KDOP_DIAGONALS; ++j) {
    lo[j] = std::fmin(lo[j], other.lo[j]);
    hi[j] = std::fmax(hi[j], other.hi[j]);
  }
}

double diagonalDot(int j, double x, double y, double z) {
  switch (j) {
    case 0:
      return x + y + z;
    case 1:
      return x + y - z;
    case 2:
      return x - y + z;
    default:
      return -x + y + z;
  }
}

DiagonalSlabs primitiveDiagonalSlabs(const ObjectGpu& object, const Aabb& box) {
  double lo[BVH_KDOP_DIAGONALS], hi[BVH_KDOP_DIAGONALS];
  for (int j = 0; j < BVH_KDOP_DIAGONALS; ++j) {
    lo[j] = std::numeric_limits<double>::infinity();
    hi[j] = -std::numeric_limits<double>::infinity();
  }
  auto add = [&](double x, double y, double z) {
    for (int j = 0; j < BVH_KDOP_DIAGONALS; ++j) {
      const double d = diagonalDot(j, x, y, z);
      lo[j] = std::fmin(lo[j], d);
      hi[j] = std::fmax(hi[j], d);
    }
  };
  if (isPacketTriangle(object)) {
    for (int k = 0; k < 3; ++k) add(object.p[3 * k], object.p[3 * k + 1], object.p[3 * k + 2]);
  } else {
    for (int c = 0; c < 8; ++c)
      add((c & 1) ? box.hi[0] : box.lo[0], (c & 2) ? box.hi[1] : box.lo[1], (c & 4) ? box.hi[2] : box.lo[2]);
  }
  DiagonalSlabs s;
  for (int j = 0; j < BVH_KDOP_DIAGONALS; ++j) {
    const double grow = (hi[j] - lo[j]) * 0x1p-20;
    s.lo[j] = std::nextafter(floatDown(lo[j] - grow), -std::numeric_limits<float>::infinity());
    s.hi[j] = std::nextafter(floatUp(hi[j] + grow), std::numeric_limits<float>::infinity());
  }
  return s;
}

}  // namespace prism
