#include "accel/prim_ref.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

bool finite3(const float* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

// Object-space box of the shape (the stored parameters), in double.
bool localBounds(const ObjectGpu& ob, double lo[3], double hi[3]) {
  const float* p = ob.p;
  switch (ob.type) {
    case OBJECT_SPHERE: {
      if (!finite3(p) || !std::isfinite(p[3])) return false;
      double r = std::fabs(double(p[3]));
      for (int a = 0; a < 3; ++a) {
        lo[a] = double(p[a]) - r;
        hi[a] = double(p[a]) + r;
      }
      return true;
    }
    case OBJECT_BOX:
      if (!finite3(p) || !finite3(p + 3)) return false;
      // box_intersect is symmetric in its two corners, so an inverted box is the
      // box the corners span.
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(p[a], p[3 + a]);
        hi[a] = std::max(p[a], p[3 + a]);
      }
      return true;
    case OBJECT_TRIANGLE:
      if (!finite3(p) || !finite3(p + 3) || !finite3(p + 6)) return false;
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min({p[a], p[3 + a], p[6 + a]});
        hi[a] = std::max({p[a], p[3 + a], p[6 + a]});
      }
      return true;
    default:
      return false;  // planes, unknown types
  }
}

// Inverse of the 3x4 world-to-object matrix in double: object-to-world.
bool invert(const float* m, double out[12]) {
  double a[3][3] = {{m[0], m[1], m[2]}, {m[4], m[5], m[6]}, {m[8], m[9], m[10]}};
  double t[3] = {m[3], m[7], m[11]};
  double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  if (!(det != 0) || !std::isfinite(det)) return false;
  double inv[3][3];
  inv[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) / det;
  inv[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det;
  inv[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det;
  inv[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) / det;
  inv[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det;
  inv[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det;
  inv[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) / det;
  inv[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det;
  inv[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out[4 * r + c] = inv[r][c];
    out[4 * r + 3] = -(inv[r][0] * t[0] + inv[r][1] * t[1] + inv[r][2] * t[2]);
  }
  return true;
}

}  // namespace

float roundDown(double x) {
  float f = static_cast<float>(x);
  if (double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}

float roundUp(double x) {
  float f = static_cast<float>(x);
  if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

bool objectBounds(const ObjectGpu& ob, Aabb* bounds) {
  double lo[3], hi[3];
  if (ob.type == OBJECT_PLANE || !localBounds(ob, lo, hi)) return false;
  if (ob.has_transform) {
    // The device maps rays into object space with the float matrix; its inverse
    // in double, padded, bounds the shape that matrix describes.
    double m[12];
    if (!invert(ob.world_to_object, m)) return false;
    double wlo[3] = {INFINITY, INFINITY, INFINITY}, whi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int corner = 0; corner < 8; ++corner) {
      double c[3] = {(corner & 1) ? hi[0] : lo[0], (corner & 2) ? hi[1] : lo[1], (corner & 4) ? hi[2] : lo[2]};
      for (int r = 0; r < 3; ++r) {
        double w = m[4 * r] * c[0] + m[4 * r + 1] * c[1] + m[4 * r + 2] * c[2] + m[4 * r + 3];
        wlo[r] = std::min(wlo[r], w);
        whi[r] = std::max(whi[r], w);
      }
    }
    double extent = 0, magnitude = 0;
    for (int a = 0; a < 3; ++a) {
      extent = std::max(extent, whi[a] - wlo[a]);
      magnitude = std::max({magnitude, std::fabs(wlo[a]), std::fabs(whi[a])});
    }
    double pad = 1e-5 * (extent + magnitude) + 1e-30;
    for (int a = 0; a < 3; ++a) {
      lo[a] = wlo[a] - pad;
      hi[a] = whi[a] + pad;
    }
  } else {
    // The kernels' float intersection routines may accept a hit a little
    // outside the exact shape (Moller-Trumbore on a ray grazing an edge, a
    // sphere's rounded discriminant): grow the box by 2^-20 of its size and
    // one more float step.
    double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    double pad = extent * 0x1p-20;
    for (int a = 0; a < 3; ++a) {
      lo[a] -= pad;
      hi[a] += pad;
    }
  }
  const float inf = std::numeric_limits<float>::infinity();
  for (int a = 0; a < 3; ++a) {
    bounds->lo[a] = std::nextafter(roundDown(lo[a]), -inf);
    bounds->hi[a] = std::nextafter(roundUp(hi[a]), inf);
    if (!std::isfinite(bounds->lo[a]) || !std::isfinite(bounds->hi[a])) return false;
  }
  return true;
}

PrimitiveSet gatherPrimitives(const std::vector<ObjectGpu>& objects) {
  PrimitiveSet set;
  set.bounded.reserve(objects.size());
  set.bounds.reserve(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    Aabb b;
    if (objectBounds(objects[i], &b)) {
      set.bounded.push_back(static_cast<std::int32_t>(i));
      set.bounds.push_back(b);
      set.scene.extend(b);
    } else {
      set.unbounded.push_back(static_cast<std::int32_t>(i));
    }
  }
  return set;
}

}  // namespace prism
