// The single triangle (three vertices), kept in world space; mesh triangles
// share its record. Kernel: kernels/geometry/triangle.h and, four at a time,
// kernels/accel/leaf_packets.h.
#include <algorithm>
#include <array>
#include <cmath>

#include "scene/primitives/cgal_cell.h"
#include "scene/primitives/primitive_kind.h"
#include "scene/value_check.h"

namespace prism {
namespace {

void parse(const JsonReader& r, const Json& v, const std::string& path, const std::string&, Object& o) {
  r.checkObject(v, path, objectKeys({"vertices"}));
  const std::string at = member(path, "vertices");
  const Json& vs = r.require(v, path, "vertices");
  if (!vs.is_array() || vs.size() != 3) r.expected(at, "an array of 3 points", vs);
  for (int k = 0; k < 3; ++k) o.vertices[k] = r.vec3(vs[k], element(at, k));
  const Vec3 e1 = o.vertices[1] - o.vertices[0], e2 = o.vertices[2] - o.vertices[0];
  // Relative test: the sine of the corner angle, so the scale of the scene does not matter.
  if (!(length(cross(e1, e2)) > 1e-12 * length(e1) * length(e2)))
    r.expected(at, "a non-degenerate triangle (area > 0)", vs);
}

std::string problem(const Object& o) {
  for (const Vec3& v : o.vertices) {
    std::string p = vectorProblem(v, "vertices");
    if (!p.empty()) return p;
  }
  return "";
}

void bake(Object& o) {
  for (Vec3& p : o.vertices) p = o.transform.applyPoint(p);
}

void flatten(const Object& o, std::size_t, const FlattenSettings&, ObjectGpu& g, std::vector<float>&) {
  for (int k = 0; k < 3; ++k) {
    g.p[3 * k] = static_cast<float>(o.vertices[k].x);
    g.p[3 * k + 1] = static_cast<float>(o.vertices[k].y);
    g.p[3 * k + 2] = static_cast<float>(o.vertices[k].z);
  }
}

bool localBounds(const ObjectGpu& g, const float*, double lo[3], double hi[3]) {
  const float* p = g.p;
  for (int a = 0; a < 9; ++a)
    if (!std::isfinite(p[a])) return false;
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::min({p[a], p[3 + a], p[6 + a]});
    hi[a] = std::max({p[a], p[3 + a], p[6 + a]});
  }
  return true;
}

bool meetsCell(const ObjectGpu& g, const float*, const CellBox& cell, std::size_t* exact_tests) {
  using cgal::K;
  using cgal::Point;
  if (exact_tests) ++*exact_tests;
  Point p[3] = {cgal::point(g.p), cgal::point(g.p + 3), cgal::point(g.p + 6)};
  if (!CGAL::collinear(p[0], p[1], p[2]))
    return CGAL::do_intersect(K::Triangle_3(p[0], p[1], p[2]), cgal::cuboid(cell));
  // A degenerate triangle is the segment between its lexicographically extreme
  // vertices (or a point); the kernel may still report hits on it.
  std::sort(p, p + 3, [](const Point& a, const Point& b) { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; });
  if (p[0] == p[2]) return cgal::pointInCell(p[0], cell);
  return CGAL::do_intersect(K::Segment_3(p[0], p[2]), cgal::cuboid(cell));
}

// Sutherland-Hodgman: the part of polygon `poly` with coordinate `axis` on the
// kept side of `value`.
void clipPolygon(std::vector<std::array<double, 3>>& poly, int axis, double value, bool keep_below) {
  std::vector<std::array<double, 3>> out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % n];
    bool a_in = keep_below ? a[axis] <= value : a[axis] >= value;
    bool b_in = keep_below ? b[axis] <= value : b[axis] >= value;
    if (a_in) out.push_back(a);
    if (a_in != b_in) {
      double s = (value - a[axis]) / (b[axis] - a[axis]);
      std::array<double, 3> p;
      for (int k = 0; k < 3; ++k) p[k] = a[k] + s * (b[k] - a[k]);
      p[axis] = value;
      out.push_back(p);
    }
  }
  poly.swap(out);
}

// The triangle clipped against the cell in double (perfect split bounds, Wald
// and Havran 2006), rounded outward.
bool clippedBounds(const ObjectGpu& g, const CellBox& cell, Aabb* out) {
  std::vector<std::array<double, 3>> poly;
  for (int k = 0; k < 3; ++k) poly.push_back({g.p[3 * k], g.p[3 * k + 1], g.p[3 * k + 2]});
  for (int a = 0; a < 3 && !poly.empty(); ++a) {
    clipPolygon(poly, a, cell.lo[a], false);
    if (!poly.empty()) clipPolygon(poly, a, cell.hi[a], true);
  }
  for (const auto& p : poly)
    for (int a = 0; a < 3; ++a) {
      out->lo[a] = std::min(out->lo[a], roundDown(p[a]));
      out->hi[a] = std::max(out->hi[a], roundUp(p[a]));
    }
  return true;
}

// The plane hit, then the inside test by the signs of the sub-triangles' normals.
std::optional<double> reference(const Object& o, const Vec3& org, const Vec3& d, double tmin, double tmax) {
  const Vec3* v = o.vertices;
  const Vec3 n = cross(v[1] - v[0], v[2] - v[0]);
  const double denom = dot(d, n);
  if (denom == 0) return std::nullopt;
  const double t = dot(v[0] - org, n) / denom;
  if (!(t > tmin && t < tmax)) return std::nullopt;
  const Vec3 p = org + d * t;
  for (int i = 0; i < 3; ++i)
    if (dot(cross(v[(i + 1) % 3] - v[i], p - v[i]), n) < 0) return std::nullopt;
  return t;
}

}  // namespace

const PrimitiveKind kTriangleKind = {ObjectType::Triangle, OBJECT_TRIANGLE, {"triangle"}, false, parse, problem, bake,
                                     flatten, localBounds, meetsCell, clippedBounds, reference};

}  // namespace prism
