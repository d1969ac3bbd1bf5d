// Affine transforms (object to world) for scene objects: a 3x4 matrix whose last
// row (0 0 0 1) is implicit.
#pragma once

#include "scene/vec3.h"

namespace prism {

struct Transform {
  double m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

  static Transform identity() { return {}; }
  static Transform translate(const Vec3& t);
  static Transform scale(const Vec3& s);
  // Rotation by `degrees` about `axis` (right-handed, counter-clockwise looking down the axis).
  static Transform rotate(const Vec3& axis, double degrees);

  bool isIdentity() const;
  // this ∘ other: applies `other` first.
  Transform operator*(const Transform& other) const;
  Vec3 applyPoint(const Vec3& p) const;
  Vec3 applyVector(const Vec3& v) const;
  // Determinant of the linear part; zero means the transform cannot be inverted.
  double determinant() const;
  Transform inverse() const;  // requires determinant() != 0
};

}  // namespace prism
