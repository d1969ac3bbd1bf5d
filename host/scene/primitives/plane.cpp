// The infinite plane (a point and a normal): unbounded, so every structure
// tests it against every ray. Kept in world space. Kernel: kernels/geometry/plane.h.
#include <cmath>

#include "scene/primitives/primitive_kind.h"
#include "scene/value_check.h"

namespace prism {
namespace {

void parse(const JsonReader& r, const Json& v, const std::string& path, const std::string&, Object& o) {
  r.checkObject(v, path, objectKeys({"point", "normal"}));
  o.point = r.vec3(r.require(v, path, "point"), member(path, "point"));
  o.normal = unitVector(r.nonZeroVec3(r.require(v, path, "normal"), member(path, "normal")));
}

std::string problem(const Object& o) { return vectorProblem(o.point, "point"); }

// Normals go through the inverse transpose.
void bake(Object& o) {
  const Transform inv = o.transform.inverse();
  const Vec3& n = o.normal;
  const Vec3 world{inv.m[0][0] * n.x + inv.m[1][0] * n.y + inv.m[2][0] * n.z,
                   inv.m[0][1] * n.x + inv.m[1][1] * n.y + inv.m[2][1] * n.z,
                   inv.m[0][2] * n.x + inv.m[1][2] * n.y + inv.m[2][2] * n.z};
  o.point = o.transform.applyPoint(o.point);
  o.normal = unitVector(world);
}

void flatten(const Object& o, std::size_t, const FlattenSettings&, ObjectGpu& g, std::vector<float>&) {
  const Vec3 n = normalize(o.normal);
  const double v[6] = {o.point.x, o.point.y, o.point.z, n.x, n.y, n.z};
  for (int i = 0; i < 6; ++i) g.p[i] = static_cast<float>(v[i]);
}

bool localBounds(const ObjectGpu&, const float*, double*, double*) { return false; }

std::optional<double> reference(const Object& o, const Vec3& org, const Vec3& d, double tmin, double tmax) {
  const double denom = dot(d, o.normal);
  if (denom == 0) return std::nullopt;
  const double t = dot(o.point - org, o.normal) / denom;
  if (t > tmin && t < tmax) return t;
  return std::nullopt;
}

}  // namespace

const PrimitiveKind kPlaneKind = {ObjectType::Plane, OBJECT_PLANE, {"plane"}, false, parse, problem, bake,
                                  flatten, localBounds, nullptr, nullptr, reference};

}  // namespace prism
