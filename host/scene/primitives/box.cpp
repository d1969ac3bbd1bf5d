// The axis-aligned box (min and max corners), intersected in object space when
// transformed. Kernel: kernels/geometry/box.h.
#include <algorithm>
#include <cmath>

#include "scene/primitives/primitive_kind.h"
#include "scene/primitives/roots.h"
#include "scene/value_check.h"

namespace prism {
namespace {

void parse(const JsonReader& r, const Json& v, const std::string& path, const std::string&, Object& o) {
  r.checkObject(v, path, objectKeys({"min", "max"}));
  o.box_min = r.vec3(r.require(v, path, "min"), member(path, "min"));
  o.box_max = r.vec3(r.require(v, path, "max"), member(path, "max"));
  if (!(o.box_min.x < o.box_max.x && o.box_min.y < o.box_max.y && o.box_min.z < o.box_max.z))
    r.fail(member(path, "max"), "expected max > min on every axis, got max " + formatVec(o.box_max) + " and min " +
                                    formatVec(o.box_min));
}

std::string problem(const Object& o) {
  std::string p = vectorProblem(o.box_min, "min");
  return p.empty() ? vectorProblem(o.box_max, "max") : p;
}

void flatten(const Object& o, std::size_t, const FlattenSettings&, ObjectGpu& g, std::vector<float>&) {
  const Vec3* corners[2] = {&o.box_min, &o.box_max};
  for (int k = 0; k < 2; ++k) {
    g.p[3 * k] = static_cast<float>(corners[k]->x);
    g.p[3 * k + 1] = static_cast<float>(corners[k]->y);
    g.p[3 * k + 2] = static_cast<float>(corners[k]->z);
  }
}

// box_intersect is symmetric in its two corners, so an inverted box is the
// box the corners span.
bool localBounds(const ObjectGpu& g, const float*, double lo[3], double hi[3]) {
  const float* p = g.p;
  for (int a = 0; a < 6; ++a)
    if (!std::isfinite(p[a])) return false;
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::min(p[a], p[3 + a]);
    hi[a] = std::max(p[a], p[3 + a]);
  }
  return true;
}

// Interval overlap with the box's own corners (its bounds are padded).
bool meetsCell(const ObjectGpu& g, const float*, const CellBox& cell, std::size_t*) {
  for (int a = 0; a < 3; ++a) {
    double lo = std::min(g.p[a], g.p[3 + a]), hi = std::max(g.p[a], g.p[3 + a]);
    if (hi < cell.lo[a] || lo > cell.hi[a]) return false;
  }
  return true;
}

// The slab test, in double.
std::optional<double> reference(const Object& o, const Vec3& org, const Vec3& dir, double tmin, double tmax) {
  double t_near = -INFINITY, t_far = INFINITY;
  for (int axis = 0; axis < 3; ++axis) {
    const double s = org[axis], d = dir[axis], lo = o.box_min[axis], hi = o.box_max[axis];
    if (d == 0) {
      if (s < lo || s > hi) return std::nullopt;
      continue;
    }
    const double t1 = (lo - s) / d, t2 = (hi - s) / d;
    t_near = std::max(t_near, std::min(t1, t2));
    t_far = std::min(t_far, std::max(t1, t2));
  }
  if (t_near > t_far) return std::nullopt;
  return nearestInside(t_near, t_far, tmin, tmax);
}

}  // namespace

const PrimitiveKind kBoxKind = {ObjectType::Box, OBJECT_BOX, {"box"}, false, parse, problem, nullptr,
                                flatten, localBounds, meetsCell, nullptr, reference};

}  // namespace prism
