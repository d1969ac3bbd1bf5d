// Object motion during the shutter: an object-to-world transform decomposed as
// translation x rotation x stretch (the polar decomposition), interpolated in
// time the way the kernels do it (kernels/geometry/motion.h): translation and
// stretch linearly, rotation by slerp. Double precision: the host's reference
// for the kernels and the source of the swept bounds the structures use.
#pragma once

#include "scene/transform.h"

namespace prism {

struct DecomposedTransform {
  Vec3 translate;
  double rotate[4] = {0, 0, 0, 1};  // unit quaternion x, y, z, w with w >= 0
  double stretch[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // symmetric
};

// Requires an invertible transform.
DecomposedTransform decompose(const Transform& transform);
// The transform at s in [0, 1] between a (s = 0) and b (s = 1).
Transform interpolate(const DecomposedTransform& a, const DecomposedTransform& b, double s);
// The angle in radians of the rotation that takes a's rotation to b's (the
// shorter way, as slerp goes).
double rotationAngle(const DecomposedTransform& a, const DecomposedTransform& b);

}  // namespace prism
