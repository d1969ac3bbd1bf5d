#include "accel/exact_predicates.h"

#include <algorithm>

#include "scene/primitives/primitive_kind.h"

namespace prism {
namespace {

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

}  // namespace

bool overlapsCell(const ObjectGpu& ob, const Aabb& bounds, const CellBox& cell, std::size_t* exact_tests) {
  Relation r = boxRelation(bounds, cell);
  if (r != Relation::Undecided) return r == Relation::Inside;
  if (ob.has_transform) return true;  // conservative: its world box overlaps the cell
  const PrimitiveKind* kind = primitiveKindOfGpu(ob.type);
  if (!kind || !kind->meets_cell) return true;
  return kind->meets_cell(ob, objectSideData(ob), cell, exact_tests);
}

Aabb clippedBounds(const ObjectGpu& ob, const Aabb& bounds, const CellBox& cell) {
  Aabb out;
  if (boxRelation(bounds, cell) == Relation::Inside) return bounds;
  const PrimitiveKind* kind = primitiveKindOfGpu(ob.type);
  if (ob.has_transform || !kind || !kind->clipped_bounds || !kind->clipped_bounds(ob, cell, &out)) out = bounds;
  for (int a = 0; a < 3; ++a) {
    out.lo[a] = std::max(out.lo[a], roundDown(cell.lo[a]));
    out.hi[a] = std::min(out.hi[a], roundUp(cell.hi[a]));
  }
  return out;
}

}  // namespace prism
