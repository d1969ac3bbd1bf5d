#include "support/reference_geometry.h"

#include <algorithm>
#include <cmath>

#include "scene/primitives/primitive_kind.h"

namespace prism::test {

std::optional<double> referenceIntersect(const Object& ob, const RefRay& world) {
  RefRay r = world;
  if (!ob.transform.isIdentity()) {
    Transform inv = ob.transform.inverse();
    r.o = inv.applyPoint(world.o);
    r.d = inv.applyVector(world.d);  // not renormalised: t is shared by both spaces
  }
  return primitiveKind(ob.type).reference(ob, r.o, r.d, r.tmin, r.tmax);
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
    case ObjectType::Polyhedron:
      // Every plane moves out (s > 1) or in along its normal by (s - 1) of
      // its distance from the origin plus one unit.
      for (std::size_t i = 0; i + 3 < o.params.size(); i += 4) {
        const double len = length(Vec3{o.params[i], o.params[i + 1], o.params[i + 2]});
        o.params[i + 3] -= (s - 1) * (len + std::fabs(o.params[i + 3]));
      }
      break;
    case ObjectType::Quadric: {
      // The solid {Q <= 0} grows as J falls, by (s - 1) of the largest
      // coefficient; the clip box scales about its centre.
      double k = 0;
      for (int i = 0; i < 10; ++i) k = std::max(k, std::fabs(o.params[i]));
      o.params[9] -= (s - 1) * k;
      for (int a = 0; a < 3; ++a) {
        double c = 0.5 * (o.params[10 + a] + o.params[13 + a]), h = 0.5 * (o.params[13 + a] - o.params[10 + a]);
        o.params[10 + a] = c - h * s;
        o.params[13 + a] = c + h * s;
      }
      break;
    }
  }
  return o;
}

}  // namespace prism::test
