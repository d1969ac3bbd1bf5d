#include "scene/object_check.h"

#include <cmath>

#include "scene/value_check.h"

namespace prism {

std::string objectProblem(const Object& o) {
  switch (o.type) {
    case ObjectType::Sphere: {
      std::string p = vectorProblem(o.center, "center");
      if (!p.empty()) return p;
      if (!(o.radius > 0 && o.radius <= kMaxCoordinate)) return "radius must be a positive number of at most 1e15";
      return "";
    }
    case ObjectType::Box: {
      std::string p = vectorProblem(o.box_min, "min");
      return p.empty() ? vectorProblem(o.box_max, "max") : p;
    }
    case ObjectType::Plane:
      return vectorProblem(o.point, "point");
    case ObjectType::Triangle:
      for (const Vec3& v : o.vertices) {
        std::string p = vectorProblem(v, "vertices");
        if (!p.empty()) return p;
      }
      return "";
    case ObjectType::Mesh:
      return "";
  }
  return "";
}

}  // namespace prism
