// Whether a primitive meets a closed cell, decided by its kind
// (scene/primitives/): exactly with CGAL's predicates where the kind has an
// exact test (triangles, untransformed spheres), so that no primitive is lost
// or wrongly kept at a cell boundary; by interval overlap for boxes; by the
// (padded) world box for transformed objects and kinds without a test.
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
