// The sphere: a centre and a radius, intersected in object space when
// transformed (an ellipsoid then). Kernel: kernels/geometry/sphere.h.
#include <cmath>

#include "scene/primitives/cgal_cell.h"
#include "scene/primitives/primitive_kind.h"
#include "scene/primitives/roots.h"
#include "scene/value_check.h"

namespace prism {
namespace {

void parse(const JsonReader& r, const Json& v, const std::string& path, const std::string&, Object& o) {
  r.checkObject(v, path, objectKeys({"center", "radius"}));
  o.center = r.vec3(r.require(v, path, "center"), member(path, "center"));
  o.radius = r.number(r.require(v, path, "radius"), member(path, "radius"), "a positive number",
                      [](double x) { return x > 0; });
}

std::string problem(const Object& o) {
  std::string p = vectorProblem(o.center, "center");
  if (!p.empty()) return p;
  if (!(o.radius > 0 && o.radius <= kMaxCoordinate)) return "radius must be a positive number of at most 1e15";
  return "";
}

void flatten(const Object& o, std::size_t, const FlattenSettings&, ObjectGpu& g, std::vector<float>&) {
  g.p[0] = static_cast<float>(o.center.x);
  g.p[1] = static_cast<float>(o.center.y);
  g.p[2] = static_cast<float>(o.center.z);
  g.p[3] = static_cast<float>(o.radius);
}

bool localBounds(const ObjectGpu& g, const float*, double lo[3], double hi[3]) {
  const float* p = g.p;
  if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || !std::isfinite(p[3])) return false;
  const double r = std::fabs(double(p[3]));
  for (int a = 0; a < 3; ++a) {
    lo[a] = double(p[a]) - r;
    hi[a] = double(p[a]) + r;
  }
  return true;
}

// The ball against the cell (the squared distance from the centre to the box
// against r^2), so a sphere enclosing a cell is kept: conservative for its surface.
bool meetsCell(const ObjectGpu& g, const float*, const CellBox& cell, std::size_t* exact_tests) {
  if (exact_tests) ++*exact_tests;
  const double r = g.p[3];  // r*r of a float is exact in double
  return CGAL::do_intersect(cgal::K::Sphere_3(cgal::point(g.p), r * r), cgal::cuboid(cell));
}

// Textbook quadratic a t^2 + b t + c = 0, in long double for headroom.
std::optional<double> reference(const Object& o, const Vec3& org, const Vec3& d, double tmin, double tmax) {
  const Vec3& c = o.center;
  long double ox = org.x - c.x, oy = org.y - c.y, oz = org.z - c.z;
  long double a = (long double)d.x * d.x + (long double)d.y * d.y + (long double)d.z * d.z;
  long double b = 2 * (ox * d.x + oy * d.y + oz * d.z);
  long double cc = ox * ox + oy * oy + oz * oz - (long double)o.radius * o.radius;
  long double disc = b * b - 4 * a * cc;
  if (disc < 0) return std::nullopt;
  long double s = std::sqrt(disc);
  return nearestInside(double((-b - s) / (2 * a)), double((-b + s) / (2 * a)), tmin, tmax);
}

}  // namespace

const PrimitiveKind kSphereKind = {ObjectType::Sphere, OBJECT_SPHERE, {"sphere"}, false, parse, problem, nullptr,
                                   flatten, localBounds, meetsCell, nullptr, reference};

}  // namespace prism
