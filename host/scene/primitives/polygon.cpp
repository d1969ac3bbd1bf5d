// The planar polygon: n >= 3 vertices in order, convex or not, but simple (its
// edges meet only at shared vertices), kept in world space. Its point-in-polygon
// step is selectable (scene/primitives/inside_test.h); whichever runs, a point
// exactly on an edge or a vertex is inside (the polygon is closed). Kernel:
// kernels/geometry/polygon.h. CGAL decides simplicity and convexity (in the
// projection onto the plane of the two axes the normal is least along), the
// reference's inside test, and the cell test (through the polygon's fan of
// triangles, which covers it).
#include <CGAL/Polygon_2.h>

#include <algorithm>
#include <cmath>

#include "scene/primitives/cgal_cell.h"
#include "scene/primitives/inside_test.h"
#include "scene/primitives/polygon_shape.h"
#include "scene/primitives/primitive_kind.h"
#include "scene/value_check.h"

namespace prism {

bool tryParseInsideTest(const std::string& name, InsideTest* test) {
  if (name == "crossing") return *test = InsideTest::Crossing, true;
  if (name == "radial") return *test = InsideTest::Radial, true;
  if (name == "left-right") return *test = InsideTest::LeftRight, true;
  return false;
}

const char* insideTestName(InsideTest test) {
  switch (test) {
    case InsideTest::Radial:
      return "radial";
    case InsideTest::LeftRight:
      return "left-right";
    case InsideTest::Crossing:
      break;
  }
  return "crossing";
}

namespace {

using Polygon2 = CGAL::Polygon_2<cgal::K>;

std::vector<Vec3> verticesOf(const Object& o) {
  std::vector<Vec3> v(o.params.size() / 3);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = {o.params[3 * i], o.params[3 * i + 1], o.params[3 * i + 2]};
  return v;
}

// Newell's normal: twice the vector area, exact for planar polygons whatever their shape.
Vec3 newellNormal(const std::vector<Vec3>& v) {
  Vec3 n;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3& a = v[i];
    const Vec3& b = v[(i + 1) % v.size()];
    n = n + Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  return n;
}

// The axis the normal is most along: dropping it projects without folding.
int dominantAxis(const Vec3& n) {
  const double a[3] = {std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)};
  return a[0] >= a[1] && a[0] >= a[2] ? 0 : a[1] >= a[2] ? 1 : 2;
}

struct Projection {
  int u, v;  // the axes kept
};
Projection projectionOf(const Vec3& n) {
  const int drop = dominantAxis(n);
  return {drop == 0 ? 1 : 0, drop == 2 ? 1 : 2};
}

Polygon2 projected(const std::vector<Vec3>& v, Projection p) {
  Polygon2 poly;
  for (const Vec3& x : v) poly.push_back(cgal::K::Point_2(x[p.u], x[p.v]));
  return poly;
}

}  // namespace

PolygonCheck checkPolygon(const std::vector<Vec3>& verts) {
  PolygonCheck c;
  double diameter = 0;
  for (const Vec3& a : verts)
    for (const Vec3& b : {verts.front(), verts[verts.size() / 2]}) diameter = std::max(diameter, length(a - b));
  const Vec3 n = newellNormal(verts);
  if (!(length(n) > 1e-12 * diameter * diameter)) {
    c.problem = "expected a polygon of non-zero area";
    c.zero_area = true;
    return c;
  }
  // Distances from the mean plane (Newell's normal through the centroid).
  const Vec3 unit = n / length(n);
  Vec3 centroid;
  for (const Vec3& x : verts) centroid = centroid + x / static_cast<double>(verts.size());
  double off = 0;
  for (std::size_t k = 0; k < verts.size(); ++k) {
    const double d = std::fabs(dot(verts[k] - centroid, unit));
    if (d > off) off = d, c.vertex = k;
  }
  if (off > 1e-6 * diameter) {
    c.problem = "expected the polygon to be planar, but this vertex lies " + formatNumber(off) +
                " off the polygon's plane (at most 1e-6 of its size)";
    return c;
  }
  c.vertex = SIZE_MAX;
  const Polygon2 poly = projected(verts, projectionOf(n));
  if (!poly.is_simple()) c.problem = "expected a simple polygon: two of its edges cross or touch (or a vertex repeats)";
  c.convex = c.problem.empty() && poly.is_convex();
  return c;
}

void flattenPolygon(const std::vector<Vec3>& verts, InsideTest test, ObjectGpu& g, std::vector<float>& side) {
  const Vec3 n = normalize(newellNormal(verts));
  const Projection pr = projectionOf(n);
  const Polygon2 poly = projected(verts, pr);
  if (test == InsideTest::LeftRight && !poly.is_convex())
    throw std::invalid_argument("inside test 'left-right' needs a convex polygon and this one is not (use crossing or radial)");
  g.type = OBJECT_POLYGON;
  const double p[9] = {n.x,  n.y,  n.z, -dot(n, verts[0]), double(pr.u), double(pr.v), double(verts.size()),
                       double(static_cast<int>(test)), poly.orientation() == CGAL::COUNTERCLOCKWISE ? 1.0 : -1.0};
  for (int i = 0; i < 9; ++i) g.p[i] = static_cast<float>(p[i]);
  for (const Vec3& v : verts) side.insert(side.end(), {float(v.x), float(v.y), float(v.z)});
}

namespace {

void parse(const JsonReader& r, const Json& v, const std::string& path, const std::string&, Object& o) {
  r.checkObject(v, path, objectKeys({"vertices", "inside_test"}));
  const std::string at = member(path, "vertices");
  const Json& vs = r.require(v, path, "vertices");
  if (!vs.is_array() || vs.size() < 3) r.expected(at, "an array of at least 3 points", vs);
  std::vector<Vec3> verts;
  for (std::size_t k = 0; k < vs.size(); ++k) {
    verts.push_back(r.vec3(vs[k], element(at, k)));
    o.params.insert(o.params.end(), {verts.back().x, verts.back().y, verts.back().z});
  }
  const PolygonCheck check = checkPolygon(verts);
  if (check.zero_area) r.expected(at, "a polygon of non-zero area", vs);
  if (!check.problem.empty()) r.fail(check.vertex == SIZE_MAX ? at : element(at, check.vertex), check.problem);
  if (const Json* t = JsonReader::find(v, "inside_test")) {
    const std::string name = r.string(*t, member(path, "inside_test"), std::string("a string (") + kInsideTestNames + ")");
    InsideTest test;
    if (!tryParseInsideTest(name, &test))
      r.fail(member(path, "inside_test"), "unknown inside test '" + name + "' (expected " + kInsideTestNames + ")");
    if (test == InsideTest::LeftRight && !check.convex)
      r.fail(member(path, "inside_test"),
             "'left-right' needs a convex polygon and this one is not (use crossing or radial)");
    o.inside_test = name;
  }
}

std::string problem(const Object& o) {
  for (const Vec3& v : verticesOf(o)) {
    std::string p = vectorProblem(v, "vertices");
    if (!p.empty()) return p;
  }
  return "";
}

void bake(Object& o) {
  for (std::size_t i = 0; i + 2 < o.params.size(); i += 3) {
    const Vec3 w = o.transform.applyPoint({o.params[i], o.params[i + 1], o.params[i + 2]});
    o.params[i] = w.x, o.params[i + 1] = w.y, o.params[i + 2] = w.z;
  }
}

void flatten(const Object& o, std::size_t, const FlattenSettings& settings, ObjectGpu& g, std::vector<float>& side) {
  InsideTest test = static_cast<InsideTest>(settings.inside_test);
  if (!o.inside_test.empty()) tryParseInsideTest(o.inside_test, &test);
  flattenPolygon(verticesOf(o), test, g, side);
}

bool localBounds(const ObjectGpu& g, const float* side, double lo[3], double hi[3]) {
  const int n = static_cast<int>(g.p[6]);
  for (int a = 0; a < 3; ++a) lo[a] = INFINITY, hi[a] = -INFINITY;
  for (int k = 0; k < 3 * n; ++k) {
    if (!std::isfinite(side[k])) return false;
    lo[k % 3] = std::min(lo[k % 3], double(side[k]));
    hi[k % 3] = std::max(hi[k % 3], double(side[k]));
  }
  return n >= 3;
}

// The fan (v0, vk, vk+1) covers the polygon, convex or not: conservative.
bool meetsCell(const ObjectGpu& g, const float* side, const CellBox& cell, std::size_t* exact_tests) {
  using cgal::K;
  const int n = static_cast<int>(g.p[6]);
  if (exact_tests) ++*exact_tests;
  const auto box = cgal::cuboid(cell);
  for (int k = 1; k + 1 < n; ++k) {
    const cgal::Point a = cgal::point(side), b = cgal::point(side + 3 * k), c = cgal::point(side + 3 * (k + 1));
    if (CGAL::collinear(a, b, c) ? CGAL::do_intersect(K::Segment_3(a, b), box) || CGAL::do_intersect(K::Segment_3(b, c), box)
                                 : CGAL::do_intersect(K::Triangle_3(a, b, c), box))
      return true;
  }
  return false;
}

// The plane hit in double, then CGAL's exact bounded-side test of its
// projection (on the boundary counts as inside).
std::optional<double> reference(const Object& o, const Vec3& org, const Vec3& dir, double tmin, double tmax) {
  const std::vector<Vec3> verts = verticesOf(o);
  const Vec3 n = newellNormal(verts);
  const double denom = dot(dir, n);
  if (denom == 0) return std::nullopt;
  const double t = dot(verts[0] - org, n) / denom;
  if (!(t > tmin && t < tmax)) return std::nullopt;
  const Vec3 p = org + dir * t;
  const Projection pr = projectionOf(n);
  const Polygon2 poly = projected(verts, pr);
  if (poly.bounded_side(cgal::K::Point_2(p[pr.u], p[pr.v])) == CGAL::ON_UNBOUNDED_SIDE) return std::nullopt;
  return t;
}

}  // namespace

const PrimitiveKind kPolygonKind = {ObjectType::Polygon, OBJECT_POLYGON, {"polygon"}, true, parse, problem, bake,
                                    flatten, localBounds, meetsCell, nullptr, reference};

}  // namespace prism
