// Whether a primitive meets a closed cell, decided exactly with CGAL's
// predicates (Exact_predicates_inexact_constructions_kernel), so that no
// primitive is lost or wrongly kept at a cell boundary:
//   triangles: do_intersect(Triangle_3, Iso_cuboid_3), or the segment / point a
//     degenerate triangle collapses to;
//   untransformed spheres: do_intersect(Sphere_3, Iso_cuboid_3), the squared
//     distance from the centre to the box against r^2 (the ball, so a sphere
//     enclosing a cell is kept: conservative for its surface);
//   untransformed boxes: interval overlap on each axis;
//   transformed objects and anything else: their (padded) world box, overlap.
// A primitive touching the cell only on its boundary counts as meeting it.
#pragma once

#include <atomic>
#include <cstddef>

#include "accel/prim_ref.h"
#include "kernels/shared/object_gpu.h"

namespace prism {

// Exact test; `bounds` is the object's box from objectBounds (used first to
// answer without CGAL when the box is clearly in or out). Adds 1 to
// `exact_tests` when CGAL had to decide.
bool overlapsCell(const ObjectGpu& object, const Aabb& bounds, const CellBox& cell, std::size_t* exact_tests);

// The box of the part of the primitive inside `cell` (perfect split bounds,
// Wald and Havran 2006), for the SAH only: a triangle is clipped against the
// cell in double; other primitives give their box cut by the cell. Rounded
// outward to float; empty when nothing is left (rounding at a touching cell).
Aabb clippedBounds(const ObjectGpu& object, const Aabb& bounds, const CellBox& cell);

}  // namespace prism
