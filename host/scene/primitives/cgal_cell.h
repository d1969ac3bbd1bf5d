// CGAL's exact predicates on the cells of a subdivision, for the kinds whose
// cell test is exact (Exact_predicates_inexact_constructions_kernel: every
// float input is exact in double, and the predicates decide exactly).
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include "scene/primitives/bounds.h"

namespace prism::cgal {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;

inline K::Iso_cuboid_3 cuboid(const CellBox& c) {
  return K::Iso_cuboid_3(c.lo[0], c.lo[1], c.lo[2], c.hi[0], c.hi[1], c.hi[2]);
}

inline Point point(const float* p) { return Point(p[0], p[1], p[2]); }

inline bool pointInCell(const Point& p, const CellBox& c) {
  return p.x() >= c.lo[0] && p.x() <= c.hi[0] && p.y() >= c.lo[1] && p.y() <= c.hi[1] && p.z() >= c.lo[2] &&
         p.z() <= c.hi[2];
}

}  // namespace prism::cgal
