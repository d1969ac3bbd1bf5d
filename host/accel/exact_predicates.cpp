#include "accel/exact_predicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <vector>
#include <cmath>

namespace prism {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;

enum class Relation { Outside, Inside, Undecided };

// From the box alone: disjoint from the cell, inside it, or neither.
Relation boxRelation(const Aabb& b, const CellBox& c) {
  bool inside = true;
  for (int a = 0; a < 3; ++a) {
    if (double(b.hi[a]) < c.lo[a] || double(b.lo[a]) > c.hi[a]) return Relation::Outside;
    if (double(b.lo[a]) < c.lo[a] || double(b.hi[a]) > c.hi[a]) inside = false;
  }
  return inside ? Relation::Inside : Relation::Undecided;
}

K::Iso_cuboid_3 cuboid(const CellBox& c) {
  return K::Iso_cuboid_3(c.lo[0], c.lo[1], c.lo[2], c.hi[0], c.hi[1], c.hi[2]);
}

Point point(const float* p) { return Point(p[0], p[1], p[2]); }

bool pointInCell(const Point& p, const CellBox& c) {
  return p.x() >= c.lo[0] && p.x() <= c.hi[0] && p.y() >= c.lo[1] && p.y() <= c.hi[1] && p.z() >= c.lo[2] &&
         p.z() <= c.hi[2];
}

bool triangleMeetsCell(const float* v, const CellBox& cell) {
  Point p[3] = {point(v), point(v + 3), point(v + 6)};
  if (!CGAL::collinear(p[0], p[1], p[2])) return CGAL::do_intersect(K::Triangle_3(p[0], p[1], p[2]), cuboid(cell));
  // A degenerate triangle is the segment between its lexicographically extreme
  // vertices (or a point); the kernel may still report hits on it.
  std::sort(p, p + 3, [](const Point& a, const Point& b) { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; });
  if (p[0] == p[2]) return pointInCell(p[0], cell);
  return CGAL::do_intersect(K::Segment_3(p[0], p[2]), cuboid(cell));
}

bool sphereMeetsCell(const float* p, const CellBox& cell) {
  double r = p[3];
  return CGAL::do_intersect(K::Sphere_3(point(p), r * r), cuboid(cell));  // r*r of a float is exact in double
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

}  // namespace

bool overlapsCell(const ObjectGpu& ob, const Aabb& bounds, const CellBox& cell, std::size_t* exact_tests) {
  Relation r = boxRelation(bounds, cell);
  if (r != Relation::Undecided) return r == Relation::Inside;
  if (ob.has_transform) return true;  // conservative: its world box overlaps the cell
  switch (ob.type) {
    case OBJECT_TRIANGLE:
      if (exact_tests) ++*exact_tests;
      return triangleMeetsCell(ob.p, cell);
    case OBJECT_SPHERE:
      if (exact_tests) ++*exact_tests;
      return sphereMeetsCell(ob.p, cell);
    case OBJECT_BOX:
      // Interval overlap with the box's own corners (its bounds are padded).
      for (int a = 0; a < 3; ++a) {
        double lo = std::min(ob.p[a], ob.p[3 + a]), hi = std::max(ob.p[a], ob.p[3 + a]);
        if (hi < cell.lo[a] || lo > cell.hi[a]) return false;
      }
      return true;
    default:
      return true;
  }
}

Aabb clippedBounds(const ObjectGpu& ob, const Aabb& bounds, const CellBox& cell) {
  Aabb out;
  if (boxRelation(bounds, cell) == Relation::Inside) return bounds;
  if (ob.type == OBJECT_TRIANGLE && !ob.has_transform) {
    std::vector<std::array<double, 3>> poly;
    for (int k = 0; k < 3; ++k) poly.push_back({ob.p[3 * k], ob.p[3 * k + 1], ob.p[3 * k + 2]});
    for (int a = 0; a < 3 && !poly.empty(); ++a) {
      clipPolygon(poly, a, cell.lo[a], false);
      if (!poly.empty()) clipPolygon(poly, a, cell.hi[a], true);
    }
    for (const auto& p : poly)
      for (int a = 0; a < 3; ++a) {
        out.lo[a] = std::min(out.lo[a], roundDown(p[a]));
        out.hi[a] = std::max(out.hi[a], roundUp(p[a]));
      }
  } else {
    out = bounds;
  }
  for (int a = 0; a < 3; ++a) {
    out.lo[a] = std::max(out.lo[a], roundDown(cell.lo[a]));
    out.hi[a] = std::min(out.hi[a], roundUp(cell.hi[a]));
  }
  return out;
}

}  // namespace prism
