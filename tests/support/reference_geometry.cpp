#include "support/reference_geometry.h"

#include <algorithm>
#include <cmath>

namespace prism::test {
namespace {

std::optional<double> pick(double t0, double t1, const RefRay& r) {
  if (t0 > t1) std::swap(t0, t1);
  if (t0 > r.tmin && t0 < r.tmax) return t0;
  if (t1 > r.tmin && t1 < r.tmax) return t1;
  return std::nullopt;
}

std::optional<double> sphere(const Vec3& c, double radius, const RefRay& r) {
  // Textbook quadratic a t^2 + b t + c = 0, in long double for headroom.
  long double ox = r.o.x - c.x, oy = r.o.y - c.y, oz = r.o.z - c.z;
  long double a = (long double)r.d.x * r.d.x + (long double)r.d.y * r.d.y + (long double)r.d.z * r.d.z;
  long double b = 2 * (ox * r.d.x + oy * r.d.y + oz * r.d.z);
  long double cc = ox * ox + oy * oy + oz * oz - (long double)radius * radius;
  long double disc = b * b - 4 * a * cc;
  if (disc < 0) return std::nullopt;
  long double s = std::sqrt(disc);
  return pick(double((-b - s) / (2 * a)), double((-b + s) / (2 * a)), r);
}

std::optional<double> box(const Vec3& lo, const Vec3& hi, const RefRay& r) {
  double t_near = -INFINITY, t_far = INFINITY;
  for (int axis = 0; axis < 3; ++axis) {
    double o = r.o[axis], d = r.d[axis];
    if (d == 0) {
      if (o < lo[axis] || o > hi[axis]) return std::nullopt;
      continue;
    }
    double t1 = (lo[axis] - o) / d, t2 = (hi[axis] - o) / d;
    t_near = std::max(t_near, std::min(t1, t2));
    t_far = std::min(t_far, std::max(t1, t2));
  }
  if (t_near > t_far) return std::nullopt;
  return pick(t_near, t_far, r);
}

std::optional<double> plane(const Vec3& p, const Vec3& n, const RefRay& r) {
  double denom = dot(r.d, n);
  if (denom == 0) return std::nullopt;
  double t = dot(p - r.o, n) / denom;
  if (t > r.tmin && t < r.tmax) return t;
  return std::nullopt;
}

std::optional<double> triangle(const Vec3* v, const RefRay& r) {
  // Plane hit, then inside test by the signs of the sub-triangle normals.
  Vec3 n = cross(v[1] - v[0], v[2] - v[0]);
  auto t = plane(v[0], n, r);
  if (!t) return std::nullopt;
  Vec3 p = r.o + r.d * *t;
  for (int i = 0; i < 3; ++i)
    if (dot(cross(v[(i + 1) % 3] - v[i], p - v[i]), n) < 0) return std::nullopt;
  return t;
}

}  // namespace

std::optional<double> referenceIntersect(const Object& ob, const RefRay& world) {
  RefRay r = world;
  if (!ob.transform.isIdentity()) {
    Transform inv = ob.transform.inverse();
    r.o = inv.applyPoint(world.o);
    r.d = inv.applyVector(world.d);  // not renormalised: t is shared by both spaces
  }
  switch (ob.type) {
    case ObjectType::Sphere: return sphere(ob.center, ob.radius, r);
    case ObjectType::Box: return box(ob.box_min, ob.box_max, r);
    case ObjectType::Plane: return plane(ob.point, ob.normal, r);
    case ObjectType::Triangle: return triangle(ob.vertices, r);
  }
  return std::nullopt;
}

Object scaledAboutCentre(const Object& object, double s) {
  Object o = object;
  switch (o.type) {
    case ObjectType::Sphere: o.radius *= s; break;
    case ObjectType::Box: {
      Vec3 c = (o.box_min + o.box_max) * 0.5;
      o.box_min = c + (o.box_min - c) * s;
      o.box_max = c + (o.box_max - c) * s;
      break;
    }
    case ObjectType::Plane:
      // A plane has no size: shift it along its normal by the same relative
      // amount of its distance from the origin (plus one unit).
      o.point = o.point + o.normal * ((s - 1) * (1 + length(o.point)));
      break;
    case ObjectType::Triangle: {
      Vec3 c = (o.vertices[0] + o.vertices[1] + o.vertices[2]) / 3.0;
      for (Vec3& v : o.vertices) v = c + (v - c) * s;
      break;
    }
  }
  return o;
}

}  // namespace prism::test
