// "Set of normals" bounds (Kay and Kajiya, "Ray tracing complex scenes",
// 1986): slabs along the four diagonals (1,1,1), (1,1,-1), (1,-1,1),
// (-1,1,1), which with the three axes' slabs of a box make a 14-sided
// polytope around a primitive or a BVH child (kernels/shared/bvh_node_gpu.h,
// BvhKdopGpu). Floats rounded outward, so each holds what it bounds.
#pragma once

#include "kernels/shared/bvh_node_gpu.h"
#include "kernels/shared/object_gpu.h"
#include "scene/primitives/bounds.h"

namespace prism {

struct DiagonalSlabs {
  float lo[BVH_KDOP_DIAGONALS], hi[BVH_KDOP_DIAGONALS];

  // Bounds nothing: every lo +inf, every hi -inf.
  static DiagonalSlabs empty();
  void extend(const DiagonalSlabs& other);
};

// Diagonal j dotted with (x, y, z), in double.
double diagonalDot(int j, double x, double y, double z);

// The slabs of a primitive whose world box is `box`: exact for a triangle in
// world space (from its vertices), the box's otherwise; grown by 2^-20 of their
// width and a float step, as the boxes are (accel/prim_ref.h), since a float
// hit test can accept a point a hair outside the exact shape.
DiagonalSlabs primitiveDiagonalSlabs(const ObjectGpu& object, const Aabb& box);

}  // namespace prism
